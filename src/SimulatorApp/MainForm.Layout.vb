Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' Where everything goes: a layout computed from the window's size, the screen's DPI and the font,
' the same on every machine (and GUI tests find the controls from the --trace output). At 96 dpi
' and normal fonts the side panel fits a 1280 × 720 window without scrolling; when it cannot fit
' (large fonts on a small screen) it scrolls, and relaying it out keeps where it was scrolled to.
Partial Friend NotInheritable Class MainForm
    Private ReadOnly _logWidths As New Dictionary(Of Integer, Integer)

    ''' <summary>Pixels at 96 dpi to pixels on this screen.</summary>
    Private Function S(px As Double) As Integer
        Return _kit.S(px)
    End Function

    ''' <summary>The size of text as it will be drawn (see <see cref="WindowKit.Measure"/>).</summary>
    Private Function Measure(text As String, font As Font, Optional width As Integer = 0) As Size
        Return _kit.Measure(text, font, width)
    End Function

    ''' <summary>The height of one line of text in <paramref name="font"/>, px.</summary>
    Private Function LineHeight(font As Font) As Integer
        Return _kit.LineHeight(font)
    End Function

    ''' <summary>Lines of text the message area shows at once; a longer message scrolls within it.</summary>
    Private Const MessageLines As Integer = 3

    ''' <summary>The message area's height: <see cref="MessageLines"/> lines whatever it says, so the controls under it never move.</summary>
    Private Function MessageHeight() As Integer
        Return MessageLines * LineHeight(_message.Font) + S(10)
    End Function

    ''' <summary>The wheel over the message area scrolls a long message within it, and the panel when the message has no more to show that way.</summary>
    Private Sub ScrollMessage(delta As Integer)
        Dim pixels = -Math.Sign(delta) * 2 * LineHeight(_message.Font)
        If Not _message.ScrollBy(pixels) Then _sideView.ScrollBy(-Math.Sign(delta) * 3 * LineHeight(Font))
    End Sub

    ''' <summary>The side panel's rows' width in a panel <paramref name="contentWidth"/> px wide.</summary>
    Private Function RowWidthFor(contentWidth As Integer) As Integer
        Return contentWidth - S(10) - S(8)
    End Function

    ''' <summary>Height of a row of buttons (see <see cref="WindowKit.ButtonRowHeight"/>).</summary>
    Private Function ButtonRowHeight() As Integer
        Return _kit.ButtonRowHeight()
    End Function

    Private Sub ArrangeControls()
        If _presenter Is Nothing Then Return
        Dim w = ClientSize.Width, h = ClientSize.Height
        Dim large = _presenter.LargeFonts
        Dim sideWidth = Math.Min(S(If(large, 470, 420)), Math.Max(S(380), CInt(w * 0.36)))
        Dim line = LineHeight(Font)
        ' With large fonts the canvas grows a little (its labels grow), and leaves the tables, whose rows are taller too, room for several rows.
        Dim canvasHeight = CInt(h * If(large, 0.64, 0.62))
        _canvas.SetBounds(0, 0, w - sideWidth, canvasHeight)
        ' The totals always have room for two lines: a total that grows (3141 collisions) never moves the tabs.
        _totals.SetBounds(S(6), canvasHeight, w - sideWidth - S(12), 2 * LineHeight(_totals.Font) + S(8))
        Dim tabsTop = _totals.Bottom
        ' Headers as tall as a line of text and a margin, as wide as their titles in bold (the chosen one is bold).
        _tabs.Padding = New Point(S(8), S(3))
        Dim header = LineHeight(Font) + S(8)
        If _tabs.ItemSize.Height <> header Then _tabs.ItemSize = New Size(S(40), header)
        _tabs.SetBounds(0, tabsTop, w - sideWidth, h - tabsTop)
        PlaceHeaderButtons(tabsTop, w - sideWidth)
        For Each list In _tables.Concat({_linkList})
            FitColumns(list, w - sideWidth - S(28))
        Next
        FitLogColumns()

        _sideView.BarWidth = S(17)
        _sideView.SetBounds(w - sideWidth, 0, sideWidth, h)
        ' Laid out for the whole width; again with room for the scroll bar when the rows are taller than the panel.
        ' At normal fonts the rows close up where the screen is too short for them with their usual spacing.
        _rows.Compact = False
        Dim contentHeight = ArrangeSide(sideWidth, large, line)
        If contentHeight > _sideView.ClientSize.Height AndAlso Not large Then
            _rows.Compact = True
            contentHeight = ArrangeSide(sideWidth, large, line)
        End If
        If contentHeight > _sideView.ClientSize.Height Then contentHeight = ArrangeSide(_sideView.ContentWidthFor(contentHeight), large, line)
        _sideView.SetContentHeight(contentHeight)
        For Each b In _side.Controls.OfType(Of Button)()
            _kit.CentreCaption(b)
        Next
        ' A label's words follow its new width (a long one drops its bracketed part where it would be cut).
        _restitutionLabel.Text = Fitted(_restitutionLabel, _presenter.RestitutionText)
        OrderTabsByPlace()
        ShowState()
        ShowMessage(_presenter.Message)
    End Sub

    ''' <summary>Places the side panel's rows for a content <paramref name="width"/> px wide; returns their height, px.</summary>
    Private Function ArrangeSide(width As Integer, large As Boolean, line As Integer) As Integer
        Dim rh = ButtonRowHeight()
        Dim sliderHeight = Math.Max(S(24), line + S(8))
        _rows.Start(S(10), S(6), RowWidthFor(width))
        ' Labels and boxes two to a row when every label fits its share; one to a row otherwise (large fonts).
        Dim fieldUsable = _rows.Width - 3 * S(6)
        Dim pairs = Not large AndAlso
            {_radiusLabel, _widthLabel, _sidesLabel}.All(Function(l) _rows.TextFits(l, CInt(fieldUsable * PanelRows.FieldShares(0)))) AndAlso
            {_massLabel, _heightLabel, _angleLabel}.All(Function(l) _rows.TextFits(l, CInt(fieldUsable * PanelRows.FieldShares(2))))

        _rows.Row(MessageHeight(), (_message, 1.0))
        ' A third each, or as wide as the longest caption each shows (Resume, Delete mode: ON) where a third is too narrow (large fonts on a small screen).
        _rows.CaptionRow(rh + S(4), (_pause, 1 / 3, {SimulationPresenter.PauseCaption, SimulationPresenter.ResumeCaption}),
                         (_reset, 1 / 3, {_reset.Text}), (_deleteMode, 1 / 3, SimulationPresenter.DeleteModeCaptions))
        _rows.Row(line + S(2), (_speedLabel, 1.0))
        _rows.Row(sliderHeight, (_speed, 1.0))
        _rows.Row(line + S(2), (_gravityLabel, 1.0))
        _rows.Row(sliderHeight, (_gravity, 1.0))
        ' The four planets in one row when their names and values fit there, else in two.
        Dim quarter = (_rows.Width - 3 * S(6)) \ 4
        If pairs AndAlso _gravityMarks.All(Function(b) _rows.TextFits(b, quarter)) Then
            _rows.Row(rh, (_gravityMarks(0), 0.25), (_gravityMarks(1), 0.25), (_gravityMarks(2), 0.25), (_gravityMarks(3), 0.25))
        Else
            _rows.Row(rh, (_gravityMarks(0), 0.5), (_gravityMarks(1), 0.5))
            _rows.Row(rh, (_gravityMarks(2), 0.5), (_gravityMarks(3), 0.5))
        End If
        _rows.Row(line + S(2), (_restitutionLabel, 1.0))
        _rows.Row(sliderHeight, (_restitution, 1.0))
        ' Friction's two boxes and their button on one row when they fit: "Friction μk [0.3] μs [0.5] [Set friction]".
        If Not (pairs AndAlso _rows.FitRow(rh + S(2), _frictionLabel, _friction, _staticFrictionLabel, _staticFriction, _setFriction)) Then
            _rows.Fields(rh, pairs, (_frictionLabel, _friction), (_staticFrictionLabel, _staticFriction))
            _rows.Row(rh + S(2), (Nothing, 0.35), (_setFriction, 0.65))
        End If
        _rows.Gap()
        _rows.Fields(rh, pairs, (_radiusLabel, _radius), (_massLabel, _mass))
        ' A regular polygon takes the circle's radius (its corners lie on that circle), mass and Fixed box.
        _rows.Fields(rh, pairs, (_sidesLabel, _sides), (_angleLabel, _angle))
        ' A polygon drawn by clicking its corners takes the mass and Fixed box too: its button sits beside the regular one's.
        LayOutAddRow(rh, pairs, _fixed, _addCircle, _addPolygon, _addCorners)
        _rows.Gap()
        _rows.Fields(rh, pairs, (_widthLabel, _rectWidth), (_heightLabel, _rectHeight))
        ' A ramp is a fixed obstacle too: its button sits beside the rectangle's.
        LayOutAddRow(rh, pairs, _rectFixed, _addRectangle, _addRamp, _addLiquid)
        _rows.Gap()
        ' The three links in one row after the spring's stiffness: a link is made by clicking its two ends.
        If pairs Then
            _rows.Row(rh + S(2), (_stiffnessLabel, 0.2), (_stiffness, 0.14), (_addSpring, 0.22), (_addRod, 0.22), (_addString, 0.22))
        Else
            _rows.Row(rh, (_stiffnessLabel, 0.55), (_stiffness, 0.45))
            _rows.Row(rh + S(2), (_addSpring, 1 / 3), (_addRod, 1 / 3), (_addString, 1 / 3))
        End If
        _rows.Gap()
        ' The container's size and its button on one row when they fit: "Container (m) [8] × [5] [Resize container]".
        _boxWidthLabel.Text = "Container (m)"
        _boxHeightLabel.Text = "×"
        _boxHeightLabel.TextAlign = ContentAlignment.MiddleCenter
        If pairs AndAlso _rows.FitRow(rh + S(2), _boxWidthLabel, _boxWidth, _boxHeightLabel, _boxHeight, _resize) Then
            ' One row.
        Else
            _boxWidthLabel.Text = "Container w (m)"
            _boxHeightLabel.Text = "h (m)"
            _boxHeightLabel.TextAlign = ContentAlignment.MiddleLeft
            _rows.Fields(rh, pairs, (_boxWidthLabel, _boxWidth), (_boxHeightLabel, _boxHeight))
            _rows.Row(rh + S(2), (Nothing, 0.35), (_resize, 0.65))
        End If
        _rows.Gap()
        If pairs Then
            ' The four view boxes in one row when their captions fit there, else two to a row.
            If Not _rows.FitRow(rh, _largeFonts, _highContrast, _arrows, _grid) Then
                _rows.Row(rh, (_largeFonts, 0.5), (_highContrast, 0.5))
                _rows.Row(rh, (_arrows, 0.5), (_grid, 0.5))
            End If
            _rows.Row(rh + S(2), (_tutorial, 0.24), (_maths, 0.28), (_open, 0.24), (_save, 0.24))
        Else
            _rows.Row(rh, (_largeFonts, 0.5), (_highContrast, 0.5))
            _rows.Row(rh, (_arrows, 0.5), (_grid, 0.5))
            _rows.Row(rh + S(2), (_tutorial, 0.5), (_maths, 0.5))
            _rows.Row(rh + S(2), (_open, 0.5), (_save, 0.5))
        End If
        _time.Arrange(_rows, line)
        _momentumBoxes.Arrange(_rows, rh, pairs)
        Return _rows.Y + S(4)
    End Function

    ''' <summary>Whether the totals line, with room for its numbers to grow, fits on one line this wide.</summary>
    Private Function TotalsFitOnOneLine(width As Integer) As Boolean
        Dim sample = String.Join("     ", _presenter.Snapshot.Totals)
        Return Measure(sample & "  −00.0", _totals.Font).Width <= width
    End Function

    ''' <summary>The margins each column of a list keeps beside its widest value and beside its header, px (set where its columns were last fitted to the window).</summary>
    Private ReadOnly _columnMargins As New Dictionary(Of BufferedListView, (Value As Integer, Header As Integer))

    ''' <summary>The least margin beside a header's caption, px: Mono draws the caption 5 px in from each edge of its column and cuts what does not fit (not scaled with the dpi).</summary>
    Private Const LeastHeaderMargin As Integer = 10

    ''' <summary>The least margin beside a value, px: Mono draws a cell's text 3 px in from its column's left edge in a box 6 px narrower than the column, and puts "…" for what does not fit; 1 px more for rounding.</summary>
    Private Const LeastValueMargin As Integer = 7

    ''' <summary>
    ''' Each column as wide as its header and values, and the spare width shared out, so no header is
    ''' clipped. Where the columns with their usual margin would be wider than the list (the Bodies
    ''' table's twelve on a 1280-px screen), the margins close up, down to a few pixels, before the
    ''' list would need a sideways scroll (to 7 px at 96 dpi, 8 at 192: a value still whole and clear of
    ''' the next column's grid line): a teacher sees every column at once. With large fonts, where
    ''' even that is too wide (the Bodies table's twelve columns at 192 dpi), the table's text steps
    ''' down a point at a time, never below the normal fonts' size, until every column shows; and
    ''' at that size, if it must, the margins beside the headers close up too, to no less than the
    ''' caption's own inset (the Bodies table's twelve at 192 dpi with large fonts when one body is a
    ''' "fixed quadrilateral").
    ''' </summary>
    Private Sub FitColumns(list As BufferedListView, available As Integer)
        Dim least = CSng(NormalFontPoints * _dpi.FontScale)
        Dim size = Font.Size
        Dim margin As Integer
        Dim headerMargin = S(12)
        Dim widths As Integer()
        Dim text As (Header As Integer, Widest As Integer)()
        Do
            UseTableFont(list, size)
            text = ColumnTextWidths(list)
            margin = S(12)
            widths = WidthsWithMargin(text, margin, headerMargin)
            Do While margin > Math.Max(S(4), LeastValueMargin) AndAlso widths.Sum() > available
                margin -= 1
                widths = WidthsWithMargin(text, margin, headerMargin)
            Loop
            If widths.Sum() <= available OrElse size <= least Then Exit Do
            size = Math.Max(least, size - CSng(_dpi.FontScale))
        Loop
        Do While headerMargin > Math.Max(LeastHeaderMargin, margin) AndAlso widths.Sum() > available
            headerMargin -= 1
            widths = WidthsWithMargin(text, margin, headerMargin)
        Loop
        _columnMargins(list) = (margin, headerMargin)
        Dim spare = Math.Max(0, available - widths.Sum()) \ widths.Length
        For i = 0 To widths.Length - 1
            list.Columns(i).Width = widths(i) + spare
        Next
        TraceColumns(list, widths)
    End Sub

    ''' <summary>
    ''' Gives a table the window's font at <paramref name="size"/> points, when it has another: at the
    ''' window's own size it takes the window's font again (Nothing: it follows the window's, which is
    ''' replaced, and the old one disposed, when large fonts are turned on or off).
    ''' </summary>
    Private Sub UseTableFont(list As BufferedListView, size As Single)
        If Math.Abs(list.Font.Size - size) < 0.01F AndAlso list.Font.FontFamily.Equals(Font.FontFamily) Then Return
        list.Font = If(Math.Abs(Font.Size - size) < 0.01F, Nothing, New Font(Font.FontFamily, size))
    End Sub

    ''' <summary>Each column's header's width and its widest value's (a typical one and what its rows hold now), px, in the list's font.</summary>
    Private Function ColumnTextWidths(list As BufferedListView) As (Header As Integer, Widest As Integer)()
        Dim result(list.Columns.Count - 1) As (Header As Integer, Widest As Integer)
        Dim rows = ShownCells(list)
        For i = 0 To result.Length - 1
            Dim widest = Measure(ColumnSample(list.Columns(i).Text, i), list.Font).Width
            For Each rowCells In rows
                If i < rowCells.Length Then widest = Math.Max(widest, Measure(rowCells(i), list.Font).Width)
            Next
            result(i) = (Measure(list.Columns(i).Text, list.Font).Width, widest)
        Next
        Return result
    End Function

    ''' <summary>
    ''' Each column's least width, px, from its text's widths: values have <paramref name="margin"/> px
    ''' beside them, a header <paramref name="headerMargin"/> px (Mono and Windows both inset its caption
    ''' by several pixels, so it keeps its full margin unless even the least font is too wide).
    ''' </summary>
    Private Shared Function WidthsWithMargin(text As (Header As Integer, Widest As Integer)(), margin As Integer, headerMargin As Integer) As Integer()
        Return text.Select(Function(t) Math.Max(t.Header + headerMargin, t.Widest + margin)).ToArray()
    End Function

    ''' <summary>The margins beside each column's widest value and beside its header in <paramref name="list"/>, px.</summary>
    Private Function ColumnMargin(list As BufferedListView) As (Value As Integer, Header As Integer)
        Dim margin As (Value As Integer, Header As Integer)
        Return If(_columnMargins.TryGetValue(list, margin), margin, (S(12), S(12)))
    End Function

    ''' <summary>
    ''' Each column's least width, px: its header, a typical value, and what its rows hold now (a
    ''' polygon's "1.23×10⁻³ × 0.500"), with the margins of <paramref name="margin"/> beside them.
    ''' </summary>
    Private Function NeededColumnWidths(list As BufferedListView, margin As (Value As Integer, Header As Integer)) As Integer()
        Return WidthsWithMargin(ColumnTextWidths(list), margin.Value, margin.Header)
    End Function

    ''' <summary>The cells of the first rows a body or link table holds now (at most 40: enough to see how wide its values run).</summary>
    Private Function ShownCells(list As BufferedListView) As List(Of String())
        Dim snap = _presenter.Snapshot
        Dim rows As New List(Of String())
        Dim t = _tables.IndexOf(list)
        If t >= 0 Then
            For r = 0 To Math.Min(40, snap.RowCount(t)) - 1
                rows.Add(snap.Cells(t, r))
            Next
        ElseIf list Is _linkList Then
            For r = 0 To Math.Min(40, snap.LinkCount) - 1
                rows.Add(snap.LinkCells(r))
            Next
        End If
        Return rows
    End Function

    Private _columnsGrownAt As Double = -1

    ''' <summary>
    ''' While time runs or bodies change: a column of the table on show that its values have outgrown
    ''' is widened (at most twice a second; columns only grow, so they do not jump about).
    ''' </summary>
    Private Sub GrowColumns(list As BufferedListView)
        Dim now = _clock.Elapsed.TotalSeconds
        If now - _columnsGrownAt < 0.5 Then Return
        _columnsGrownAt = now
        Dim widths = NeededColumnWidths(list, ColumnMargin(list))
        Dim grew = False
        For i = 0 To widths.Length - 1
            If list.Columns(i).Width < widths(i) Then
                list.Columns(i).Width = widths(i)
                grew = True
            End If
        Next
        If grew Then TraceColumns(list, widths)
    End Sub

    ''' <summary>With --trace: each column's width and the width its header and values need ("column Bodies 9 width 180 needs 150").</summary>
    Private Sub TraceColumns(list As BufferedListView, needs As Integer())
        If _trace Is Nothing Then Return
        Dim t = _tables.IndexOf(list)
        Dim name = If(t >= 0, SimulationPresenter.Tables(t).Title, LinkTable.Title)
        For i = 0 To needs.Length - 1
            _trace("column " & name & " " & i & " width " & list.Columns(i).Width & " needs " & needs(i))
        Next
        TraceColumnEdge(list)
    End Sub

    ''' <summary>
    ''' With --trace: where the last column ends and how wide the list's visible part is, less a
    ''' vertical scroll bar when its rows need one ("columns Bodies right 812 visible 836"). A right
    ''' edge past the visible width means the teacher must scroll sideways to see the last columns.
    ''' </summary>
    Private Sub TraceColumnEdge(list As BufferedListView)
        If _trace Is Nothing OrElse Not list.IsHandleCreated Then Return
        Dim t = _tables.IndexOf(list)
        Dim name = If(t >= 0, SimulationPresenter.Tables(t).Title, LinkTable.Title)
        Dim right = 0
        For Each c As ColumnHeader In list.Columns
            right += c.Width
        Next
        Dim visible = list.ClientSize.Width
        ' Mono counts the vertical scroll bar inside the client area; Windows does not. Either way the
        ' columns must end before it when the rows need it.
        If list.VirtualListSize > 0 AndAlso list.GetItemRect(list.VirtualListSize - 1).Bottom > list.ClientSize.Height Then
            visible = Math.Min(visible, list.Width - SystemInformation.VerticalScrollBarWidth - 2 * SystemInformation.Border3DSize.Width)
        End If
        _trace("columns " & name & " right " & right & " visible " & visible)
    End Sub

    ''' <summary>The widest text a table column usually holds, by its header: ids, colours, kinds and ends are words; the rest numbers.</summary>
    Private Shared Function ColumnSample(header As String, index As Integer) As String
        Select Case header
            Case "Kind" : Return If(index = 1, "spring, k 1000 N/m", "rectangle")
            Case "End B" : Return "anchor (0.00, 0.00)"
            ' A body's size in words runs from "r 0.250" and "length 2.83" to a box's or a polygon's "0.800 × 0.761".
            Case "Size (m)", BodyTable.SizeHeader : Return "0.000 × 0.000"
            Case "Colour" : Return "#888888"
            ' Only a velocity's components are usually negative: a position in a walled container, a speed, a mass, a size or a density is not (a column grows when one is).
            Case "vx (m/s)", "vy (m/s)" : Return "−0.000"
        End Select
        Return If(index = 0, "ball00", "0.000")
    End Function

    ''' <summary>
    ''' Each log column as wide as the widest of its header and the rows it holds (it only grows, so
    ''' columns do not jump about); the list scrolls sideways when they are wider than it.
    ''' </summary>
    Private Sub FitLogColumns()
        Dim log = _presenter.Log
        For i = 0 To _logList.Columns.Count - 1
            Dim widest = Measure(_logList.Columns(i).Text, _logList.Font).Width
            Dim previous As Integer
            If _logWidths.TryGetValue(i, previous) Then widest = Math.Max(widest, previous)
            For k = 0 To Math.Min(log.Count, 40) - 1
                widest = Math.Max(widest, Measure(log(k).Cells()(i), _logList.Font).Width)
            Next
            _logWidths(i) = widest
            Dim wanted = widest + S(16)
            If _logList.Columns(i).Width <> wanted Then
                _logList.Columns(i).Width = wanted
                _trace?.Invoke("log column " & i & " width " & wanted & " needs " & widest)
            End If
        Next
    End Sub

    ''' <summary>With --trace: every control's screen rectangle and the canvas transform, for GUI tests.</summary>
    Private Sub TraceLayout()
        If _trace Is Nothing Then Return
        Dim named = NamedControls()
        For Each n In named
            Dim p = n.Control.PointToScreen(Point.Empty)
            ' Whether its caption fits (buttons, check boxes and one-line labels; 1 for the rest).
            Dim c = n.Control
            Dim captioned = TypeOf c Is Button OrElse TypeOf c Is CheckBox OrElse (TypeOf c Is Label AndAlso c IsNot _message AndAlso c IsNot _totals)
            Dim fits = Not captioned OrElse _rows.TextFits(c, c.Width)
            _trace("control " & n.Name & " " & p.X & " " & p.Y & " " & c.Width & " " & c.Height & " " & If(fits, "fits", "cut"))
            ' The parts that must grow with the text: a check box's box, a slider's thumb.
            Dim check = TryCast(c, ScaledCheckBox)
            If check IsNot Nothing Then _trace("part " & n.Name & " box " & check.BoxSize & " " & check.BoxSize)
            Dim slider = TryCast(c, ScaledSlider)
            If slider IsNot Nothing Then _trace("part " & n.Name & " thumb " & slider.ThumbWidth & " " & slider.ThumbHeight)
            Dim button = TryCast(c, Button)
            If button IsNot Nothing Then TraceCaptionHeight(n.Name, button)
        Next
        _trace("text line " & LineHeight(Font) & " px, scroll bar " & _sideView.BarWidth & " px, panel overflow " & _sideView.Overflow & " px, scrolled " & _sideView.Offset & " px")
        ' The tabs' headers, so tests can open a table as a teacher would: "tab-links", "tab-bodies".
        For i = 0 To _tabs.TabCount - 1
            Dim r = _tabs.GetTabRect(i)
            Dim p = _tabs.PointToScreen(r.Location)
            Dim fits = Measure(_tabs.TabPages(i).Text, Font).Width <= r.Width
            _trace("control tab-" & _tabs.TabPages(i).Text.ToLowerInvariant().Replace(" "c, "-"c) & " " & p.X & " " & p.Y & " " & r.Width & " " & r.Height & If(fits, " fits", " cut"))
        Next
        Dim client = PointToScreen(Point.Empty)
        _cells.TraceCells(_tabs.SelectedIndex)
        _trace("window " & client.X & " " & client.Y & " " & ClientSize.Width & " " & ClientSize.Height)
        Dim v = _presenter.View
        _trace("view scale " & Units.Num(v.Scale, 4) & " origin " & Units.Num(v.OffsetX, 2) & " " & Units.Num(v.OffsetY, 2))
        _trace("ready")
    End Sub

    ''' <summary>
    ''' With --trace: the height a button's caption takes as the button places it, and the button's
    ''' inside ("caption add-circle client 53 padding 1 0 line 44 placed 44"). A caption aligned to
    ''' the top is placed by the text's measured height; one centred is placed by the font's height
    ''' as the toolkit reports it, which under Mono at a desktop's Xft.dpi is far more than the text
    ''' drawn (95 px for a 44-px line), so it lands low and cut in a button only as tall as the text needs.
    ''' </summary>
    Private Sub TraceCaptionHeight(name As String, b As Button)
        Dim line = LineHeight(b.Font)
        Dim topAligned = b.TextAlign = ContentAlignment.TopCenter OrElse b.TextAlign = ContentAlignment.TopLeft OrElse b.TextAlign = ContentAlignment.TopRight
        Dim placed = If(topAligned, line, Math.Max(line, b.Font.Height))
        _trace("caption " & name & " client " & b.ClientSize.Height & " padding " & b.Padding.Top & " " & b.Padding.Bottom & " line " & line & " placed " & placed)
    End Sub

    ''' <summary>The controls GUI tests know by name, with their names (see the "control" trace lines).</summary>
    Private Function NamedControls() As List(Of (Name As String, Control As Control))
        Dim named As New List(Of (Name As String, Control As Control)) From {
            ("canvas", _canvas), ("totals", _totals), ("message", _message), ("pause", _pause), ("reset", _reset), ("delete-mode", _deleteMode),
            ("speed-label", _speedLabel), ("speed", _speed), ("gravity-label", _gravityLabel), ("gravity", _gravity),
            ("restitution-label", _restitutionLabel), ("restitution", _restitution),
            ("friction-label", _frictionLabel), ("friction", _friction), ("static-friction-label", _staticFrictionLabel),
            ("static-friction", _staticFriction), ("set-friction", _setFriction),
            ("radius-label", _radiusLabel), ("mass-label", _massLabel), ("rect-width-label", _widthLabel), ("rect-height-label", _heightLabel),
            ("box-width-label", _boxWidthLabel), ("box-height-label", _boxHeightLabel),
            ("moon", _gravityMarks(0)), ("mars", _gravityMarks(1)), ("earth", _gravityMarks(2)), ("jupiter", _gravityMarks(3)),
            ("radius", _radius), ("mass", _mass), ("fixed", _fixed), ("add-circle", _addCircle),
            ("rect-width", _rectWidth), ("rect-height", _rectHeight), ("rect-fixed", _rectFixed), ("add-rectangle", _addRectangle),
            ("sides-label", _sidesLabel), ("sides", _sides), ("angle-label", _angleLabel), ("angle", _angle), ("add-polygon", _addPolygon), ("add-corners", _addCorners),
            ("stiffness-label", _stiffnessLabel), ("stiffness", _stiffness),
            ("add-spring", _addSpring), ("add-rod", _addRod), ("add-string", _addString), ("add-ramp", _addRamp),
            ("box-width", _boxWidth), ("box-height", _boxHeight), ("resize", _resize),
            ("large-fonts", _largeFonts), ("high-contrast", _highContrast), ("arrows", _arrows), ("grid", _grid),
            ("tutorial", _tutorial), ("maths", _maths), ("open", _open), ("save", _save), ("tabs", _tabs), ("side", _sideView)}
        named.Add(("scenes", _scenes))
        named.AddRange(LiquidControls())
        named.Add(("restart", _restart))
        named.Add(("export", _export))
        named.Add(("solver", _solver))
        named.Add(("measure", _measure))
        named.AddRange(_graphs.Controls(_tabs.SelectedTab Is _graphs.Page))
        named.AddRange(_forcesPage.Controls(_tabs.SelectedTab Is _forcesPage.Page))
        named.AddRange(_momentumBoxes.Controls())
        named.AddRange(_time.Controls())
        Return named
    End Function

    ''' <summary>Tab goes through the side panel as it reads: row by row, left to right (the order the controls were made in is not that).</summary>
    Private Sub OrderTabsByPlace()
        ' A text box sits a few pixels lower than the buttons of its row (it is centred in it): controls
        ' whose tops are that close are one row.
        Dim byTop = _side.Controls.Cast(Of Control)().OrderBy(Function(c) c.Top).ToList()
        Dim index = 0, first = 0
        Do While first < byTop.Count
            Dim last = first
            Do While last + 1 < byTop.Count AndAlso byTop(last + 1).Top < byTop(first).Top + S(12)
                last += 1
            Loop
            For Each c In byTop.Skip(first).Take(last - first + 1).OrderBy(Function(x) x.Left)
                c.TabIndex = index
                index += 1
            Next
            first = last + 1
        Loop
    End Sub

    ''' <summary>
    ''' The header row, right of the tabs (<paramref name="top"/> px down, ending <paramref name="right"/>
    ''' px across): the solver, Export, Scenes and Restart, each as wide as its caption (the solver's
    ''' as its longest, so it never moves), in the theme's colours. Where the tabs are shorter than
    ''' the buttons they move down, so the buttons end level with them; where the tabs' headers would
    ''' run under the buttons (a small screen, large fonts) the tabs go under the row.
    ''' </summary>
    Private Sub PlaceHeaderButtons(top As Integer, right As Integer)
        Dim header = If(_tabs.TabCount > 0, _tabs.GetTabRect(0).Height, LineHeight(Font) + S(8))
        Dim height = ButtonRowHeight()
        Dim extra = Math.Max(0, height - header)
        If extra > 0 Then _tabs.SetBounds(_tabs.Left, top + extra, _tabs.Width, Math.Max(1, _tabs.Height - extra))
        Dim x = right - S(6)
        For Each b In {_restart, _scenes, _export, _solver, _measure}
            Dim captions = If(b Is _solver, SolverMenu.Captions(), {b.Text})
            Dim width = Math.Max(S(90), captions.Max(Function(c) Measure(c, Font).Width) + S(24))
            x -= width
            b.SetBounds(x, top, width, height)
            x -= S(6)
        Next
        Dim theme = _presenter.Theme
        ' Their font is the window's, taken from it (a font of their own would be disposed of when large fonts change it).
        For Each b In {_solver, _export, _scenes, _restart, _measure}
            WindowKit.Style(b, theme)
            _kit.CentreCaption(b)
        Next
        _graphs.Restyle()
        _forcesPage.Restyle()
        If _tabs.TabCount > 0 Then
            Dim lastTab = _tabs.GetTabRect(_tabs.TabCount - 1)
            If _tabs.Left + lastTab.Right > _measure.Left - S(4) AndAlso _tabs.Top < _export.Bottom Then
                Dim below = _export.Bottom + S(2)
                _tabs.SetBounds(_tabs.Left, below, _tabs.Width, Math.Max(1, _tabs.Bottom - below))
            End If
            ' The strip right of the last header, in the panel's colour (under the header buttons).
            Dim last = _tabs.GetTabRect(_tabs.TabCount - 1)
            _tabStripFill.SetBounds(_tabs.Left + last.Right + S(2), _tabs.Top, Math.Max(1, _tabs.Width - last.Right - S(2)), last.Bottom)
            _tabStripFill.BringToFront()
        End If
        For Each b In {_solver, _export, _scenes, _restart, _measure}
            b.BringToFront()
        Next
    End Sub

    ''' <summary>
    ''' A Fixed box and three Add buttons (a circle's, a polygon's and by corners; a rectangle's, a ramp's and a
    ''' liquid's): one row when all four fit, else the third button under the second in two columns, or, in one
    ''' column, each button on a row of its own beside the box's place.
    ''' </summary>
    Private Sub LayOutAddRow(rh As Integer, pairs As Boolean, box As Control, first As Control, second As Control, third As Control)
        If pairs AndAlso _rows.FitRow(rh + S(2), box, first, second, third) Then Return
        If pairs Then
            _rows.Row(rh + S(2), (box, 0.2), (first, 0.4), (second, 0.4))
            _rows.Row(rh + S(2), (Nothing, 0.2), (Nothing, 0.4), (third, 0.4))
        Else
            _rows.Row(rh + S(2), (box, 0.35), (first, 0.65))
            _rows.Row(rh + S(2), (Nothing, 0.35), (second, 0.65))
            _rows.Row(rh + S(2), (Nothing, 0.35), (third, 0.65))
        End If
    End Sub
End Class
