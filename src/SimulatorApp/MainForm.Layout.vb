Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' Where everything goes: a fixed layout computed from the window size and the font, so it is the
' same on every machine (and GUI tests can find controls from the --trace output).
Partial Friend NotInheritable Class MainForm
    Private _rowY As Integer
    Private _rowX As Integer
    Private _rowWidth As Integer

    ''' <summary>Pixels at 96 dpi to pixels on this screen.</summary>
    Private Function S(px As Double) As Integer
        Dim f = If(CurrentAutoScaleDimensions.Width > 0, CurrentAutoScaleDimensions.Width / 96.0, 1.0)
        Return CInt(Math.Round(px * f))
    End Function

    Private Sub ArrangeControls()
        Dim w = ClientSize.Width, h = ClientSize.Height
        Dim sideWidth = S(If(_presenter.LargeFonts, 480, 420))
        Dim line = Font.Height
        Dim canvasHeight = CInt(h * 0.62)
        _canvas.SetBounds(0, 0, w - sideWidth, canvasHeight)
        ' With large fonts the totals take two lines rather than being cut short.
        _totals.SetBounds(S(6), canvasHeight, w - sideWidth - S(12), If(_presenter.LargeFonts, 2 * line + S(8), line + S(10)))
        Dim tabsTop = _totals.Bottom
        _tabs.SetBounds(0, tabsTop, w - sideWidth, h - tabsTop)
        _side.SetBounds(w - sideWidth, 0, sideWidth, h)
        For Each list In {_circleTable, _rectangleTable}
            FitColumns(list, w - sideWidth - S(28))
        Next
        ' Each log column as wide as its header or a typical entry, whichever is wider; the list scrolls sideways.
        For i = 0 To _logList.Columns.Count - 1
            Dim c = _logList.Columns(i)
            c.Width = Math.Max(TextRenderer.MeasureText(c.Text, _logList.Font).Width, TextRenderer.MeasureText(LogSamples(i), _logList.Font).Width) + S(16)
        Next

        Dim rh = Math.Max(S(30), line + S(12))
        Dim sliderHeight = Math.Max(S(45), _speed.PreferredSize.Height)
        Dim pairs = Not _presenter.LargeFonts
        _side.AutoScrollPosition = New Point(0, 0)
        _rowY = S(8)
        _rowX = S(10)
        _rowWidth = sideWidth - S(10) - S(24) ' room for the vertical scroll bar

        Row(2 * line + S(14), (_message, 1.0))
        Row(rh + S(6), (_pause, 1 / 3), (_reset, 1 / 3), (_deleteMode, 1 / 3))
        Gap()
        Row(rh, (_speedLabel, 1.0))
        Row(sliderHeight, (_speed, 1.0))
        Row(rh, (_gravityLabel, 1.0))
        Row(sliderHeight, (_gravity, 1.0))
        If pairs Then
            Row(rh, (_gravityMarks(0), 0.25), (_gravityMarks(1), 0.25), (_gravityMarks(2), 0.25), (_gravityMarks(3), 0.25))
        Else
            Row(rh, (_gravityMarks(0), 0.5), (_gravityMarks(1), 0.5))
            Row(rh, (_gravityMarks(2), 0.5), (_gravityMarks(3), 0.5))
        End If
        Gap()
        Row(rh, (_restitutionLabel, 1.0))
        Row(sliderHeight, (_restitution, 1.0))
        Row(rh, (_addCircleLabel, 1.0))
        Fields(rh, pairs, (_radiusLabel, _radius), (_massLabel, _mass))
        Row(rh + S(4), (_fixed, 0.35), (_addCircle, 0.65))
        Gap()
        Row(rh, (_addRectangleLabel, 1.0))
        Fields(rh, pairs, (_widthLabel, _rectWidth), (_heightLabel, _rectHeight))
        Row(rh + S(4), (Nothing, 0.35), (_addRectangle, 0.65))
        Gap()
        Row(rh, (_containerLabel, 1.0))
        Fields(rh, pairs, (_boxWidthLabel, _boxWidth), (_boxHeightLabel, _boxHeight))
        Row(rh + S(4), (Nothing, 0.35), (_resize, 0.65))
        Gap()
        If pairs Then
            Row(rh, (_largeFonts, 0.38), (_highContrast, 0.4), (_arrows, 0.22))
        Else
            Row(rh, (_largeFonts, 1.0))
            Row(rh, (_highContrast, 1.0))
            Row(rh, (_arrows, 1.0))
        End If
        If pairs Then
            Row(rh + S(4), (_tutorial, 0.25), (_maths, 0.27), (_open, 0.24), (_save, 0.24))
        Else
            Row(rh + S(4), (_tutorial, 0.5), (_maths, 0.5))
            Row(rh + S(4), (_open, 0.5), (_save, 0.5))
        End If
    End Sub

    ''' <summary>Each column as wide as its header, and the spare width shared out, so no header is clipped.</summary>
    Private Sub FitColumns(list As BufferedListView, available As Integer)
        Dim widths(list.Columns.Count - 1) As Integer
        ' Headers are wider than the numbers under them, except for the id and colour columns.
        For i = 0 To widths.Length - 1
            Dim sample = If(i = 0, "ball00", If(i = 1, "#888888", ""))
            widths(i) = Math.Max(TextRenderer.MeasureText(list.Columns(i).Text, list.Font).Width, TextRenderer.MeasureText(sample, list.Font).Width) + S(10)
        Next
        Dim spare = Math.Max(0, available - widths.Sum()) \ widths.Length
        For i = 0 To widths.Length - 1
            list.Columns(i).Width = widths(i) + spare
        Next
    End Sub

    Private Sub Gap()
        _rowY += S(3)
    End Sub

    ''' <summary>Two labelled text boxes side by side, or one above the other with large fonts.</summary>
    Private Sub Fields(height As Integer, pairs As Boolean, ParamArray fields As (Label As Label, Box As TextBox)())
        If pairs Then
            Row(height, (fields(0).Label, 0.27), (fields(0).Box, 0.22), (fields(1).Label, 0.27), (fields(1).Box, 0.24))
        Else
            For Each f In fields
                Row(height, (f.Label, 0.55), (f.Box, 0.45))
            Next
        End If
    End Sub

    ''' <summary>One row of the side panel: controls side by side, each with a share of the width.</summary>
    Private Sub Row(height As Integer, ParamArray items As (Control As Control, Share As Double)())
        Dim gap = S(6)
        Dim usable = _rowWidth - gap * (items.Length - 1)
        Dim x = _rowX
        For Each item In items
            Dim width = CInt(usable * item.Share)
            If item.Control IsNot Nothing Then
                Dim ctlHeight = If(TypeOf item.Control Is TextBox, Math.Min(height, item.Control.PreferredSize.Height), height)
                item.Control.SetBounds(x, _rowY + (height - ctlHeight) \ 2, width, ctlHeight)
            End If
            x += width + gap
        Next
        _rowY += height + S(4)
    End Sub

    ''' <summary>With --trace: every control's screen rectangle and the canvas transform, for GUI tests.</summary>
    Private Sub TraceLayout()
        If _trace Is Nothing Then Return
        Dim named As (Name As String, Control As Control)() = {
            ("canvas", _canvas), ("pause", _pause), ("reset", _reset), ("delete-mode", _deleteMode),
            ("speed", _speed), ("gravity", _gravity), ("restitution", _restitution),
            ("moon", _gravityMarks(0)), ("mars", _gravityMarks(1)), ("earth", _gravityMarks(2)), ("jupiter", _gravityMarks(3)),
            ("radius", _radius), ("mass", _mass), ("fixed", _fixed), ("add-circle", _addCircle),
            ("rect-width", _rectWidth), ("rect-height", _rectHeight), ("add-rectangle", _addRectangle),
            ("box-width", _boxWidth), ("box-height", _boxHeight), ("resize", _resize),
            ("large-fonts", _largeFonts), ("high-contrast", _highContrast), ("arrows", _arrows),
            ("tutorial", _tutorial), ("maths", _maths), ("open", _open), ("save", _save), ("tabs", _tabs)}
        For Each n In named
            Dim p = n.Control.PointToScreen(Point.Empty)
            _trace("control " & n.Name & " " & p.X & " " & p.Y & " " & n.Control.Width & " " & n.Control.Height)
        Next
        Dim v = _presenter.View
        _trace("view scale " & Units.Num(v.Scale, 4) & " origin " & Units.Num(v.OffsetX, 2) & " " & Units.Num(v.OffsetY, 2))
        _trace("ready")
    End Sub
End Class
