Option Strict On
Imports System.Windows.Forms

''' <summary>
''' Lays the side panel out in rows, top to bottom: each row a height and its controls side by side,
''' each with a share of the row's width. It remembers where the next row goes; the panel's parts
''' (the player row, the momentum boxes) add their rows through it.
''' </summary>
Friend NotInheritable Class PanelRows
    ''' <summary>Shares of a row of two labelled boxes: label, box, label, box.</summary>
    Public Shared ReadOnly FieldShares As Double() = {0.37, 0.15, 0.25, 0.23}

    Private ReadOnly _kit As WindowKit
    Private _x As Integer

    Public Sub New(kit As WindowKit)
        _kit = kit
    End Sub

    ''' <summary>Where the next row goes, px from the panel's top.</summary>
    Public ReadOnly Property Y As Integer

    ''' <summary>The rows' width, px.</summary>
    Public ReadOnly Property Width As Integer

    ''' <summary>Starts again at the top, for rows <paramref name="width"/> px wide, <paramref name="left"/> px from the panel's edge.</summary>
    Public Sub Start(left As Integer, top As Integer, width As Integer)
        _x = left
        _Y = top
        _Width = width
    End Sub

    ''' <summary>
    ''' Rows closer together (1 px apart, groups too): on a screen too short for the panel at normal
    ''' fonts (1280 × 720, 1024 × 768), so it fits without scrolling.
    ''' </summary>
    Public Property Compact As Boolean

    ''' <summary>A little space between groups of rows.</summary>
    Public Sub Gap()
        _Y += _kit.S(If(Compact, 1, 4))
    End Sub

    ''' <summary>One row: controls side by side, each with a share of the width (Nothing leaves its share empty).</summary>
    Public Sub Row(height As Integer, ParamArray items As (Control As Control, Share As Double)())
        Dim gap = _kit.S(6)
        Dim usable = Width - gap * (items.Length - 1)
        Dim x = _x
        Dim tallest = height
        For Each item In items
            Dim w = CInt(usable * item.Share)
            If item.Control IsNot Nothing Then
                ' A text box is as tall as a line of its text and a little (a multiline one, as the side
                ' panel's are, takes that height), or as Mono insists on making a single-line one (from
                ' the DPI it reports, later, whatever it is given).
                Dim box = TryCast(item.Control, TextBox)
                Dim boxHeight = If(box Is Nothing, height, If(box.Multiline, _kit.OneLineHeight(box.Font), Math.Max(_kit.LineHeight(box.Font) + _kit.S(8), box.PreferredHeight)))
                Dim ctlHeight = Math.Min(height, boxHeight)
                item.Control.SetBounds(x, Y + (height - ctlHeight) \ 2, w, ctlHeight)
                ' Mono keeps a one-line text box as tall as the DPI it reports asks: the row grows to hold it.
                If item.Control.Height > height Then
                    item.Control.Top = Y
                    tallest = Math.Max(tallest, item.Control.Height)
                End If
            End If
            x += w + gap
        Next
        _Y += tallest + _kit.S(If(Compact, 1, 3))
    End Sub

    ''' <summary>Two labelled text boxes side by side, or one above the other (<paramref name="pairs"/> False: large fonts).</summary>
    Public Sub Fields(height As Integer, pairs As Boolean, ParamArray fields As (Label As Label, Box As TextBox)())
        If pairs Then
            Row(height, (fields(0).Label, FieldShares(0)), (fields(0).Box, FieldShares(1)), (fields(1).Label, FieldShares(2)), (fields(1).Box, FieldShares(3)))
        Else
            For Each f In fields
                Row(height, (f.Label, 0.55), (f.Box, 0.45))
            Next
        End If
    End Sub

    ''' <summary>
    ''' One row when every control's caption fits: each as wide as its caption needs (a text box as
    ''' wide as five digits), and the width left over shared out in proportion. Returns False,
    ''' placing nothing, when they do not fit.
    ''' </summary>
    Public Function FitRow(height As Integer, ParamArray controls As Control()) As Boolean
        Dim needed = controls.Select(Function(c) NeededWidth(c)).ToArray()
        Dim usable = Width - _kit.S(6) * (controls.Length - 1)
        Dim total = needed.Sum()
        If total > usable Then Return False
        Row(height, controls.Select(Function(c, i) (c, needed(i) * (usable / total) / usable)).ToArray())
        Return True
    End Function

    ''' <summary>
    ''' One row whose places do not depend on what the controls say now: each control gets its share
    ''' of the width or, where that share is too narrow for the longest caption the control can show,
    ''' that caption's width, taken from the controls with room to spare (those with no captions give
    ''' what they need not keep). So a caption that changes (Pause and Resume) never moves a control,
    ''' and a wide one (large fonts on a small screen) is not cut.
    ''' </summary>
    Public Sub CaptionRow(height As Integer, ParamArray items As (Control As Control, Share As Double, Captions As String())())
        Dim usable = Width - _kit.S(6) * (items.Length - 1)
        Dim shares = items.Select(Function(i) i.Share).ToArray()
        If usable > 0 Then
            Dim needs = items.Select(Function(i) If(i.Captions Is Nothing, 0.0, i.Captions.Max(Function(t) NeededWidth(i.Control, t)) / usable)).ToArray()
            Dim grown = Enumerable.Range(0, items.Length).Sum(Function(k) Math.Max(0.0, needs(k) - shares(k)))
            If grown > 0 Then
                Dim spare = Enumerable.Range(0, items.Length).Select(Function(k) Math.Max(0.0, shares(k) - needs(k))).ToArray()
                Dim room = spare.Sum()
                Dim taken = Math.Min(grown, room)
                For k = 0 To items.Length - 1
                    shares(k) = Math.Max(shares(k), needs(k)) - If(room > 0, spare(k) * taken / room, 0.0)
                Next
            End If
        End If
        Row(height, items.Select(Function(i, k) (i.Control, shares(k))).ToArray())
    End Sub

    ''' <summary>The least width a control of the side panel needs for its caption (or, a text box, five digits), px.</summary>
    Public Function NeededWidth(c As Control) As Integer
        If c Is Nothing Then Throw New ArgumentNullException(NameOf(c))
        Return NeededWidth(c, c.Text)
    End Function

    ''' <summary>The least width <paramref name="c"/> needs to show <paramref name="caption"/> whole (a text box: five digits), px.</summary>
    Public Function NeededWidth(c As Control, caption As String) As Integer
        If c Is Nothing Then Throw New ArgumentNullException(NameOf(c))
        If TypeOf c Is TextBox Then Return _kit.Measure("00000", c.Font).Width + _kit.S(8)
        Dim box = TryCast(c, ScaledCheckBox)
        Return _kit.Measure(caption, c.Font).Width + If(box IsNot Nothing, box.CaptionOffset + _kit.S(2), _kit.S(10)) + _kit.S(2)
    End Function

    ''' <summary>Whether a control's caption fits in <paramref name="w"/> px (with a button's edges or a check box's box).</summary>
    Public Function TextFits(c As Control, w As Integer) As Boolean
        If c Is Nothing Then Throw New ArgumentNullException(NameOf(c))
        Dim box = TryCast(c, ScaledCheckBox)
        Dim room = w - If(box IsNot Nothing, box.CaptionOffset + _kit.S(2), _kit.S(10))
        Return _kit.Measure(c.Text, c.Font).Width <= room
    End Function
End Class
