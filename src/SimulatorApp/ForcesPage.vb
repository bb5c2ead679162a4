Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The Forces tab: a box that draws the free-body diagram on the canvas, the body it is of, the forces on it
''' (kind, what exerts it, size in N, direction in degrees) and ΣF beside m a; under them the air (on or off, its
''' density: ticking the box or applying a density switches it on) and the chosen body's drag (C_d, b). What is shown is the presenter's (its <see cref="FreeBodyView"/>);
''' this only lays it out and refreshes it a few times a second.
''' </summary>
Friend NotInheritable Class ForcesPage
    Implements IDisposable

    ''' <summary>Real time between refreshes of the list while the page is on show, s.</summary>
    Private Const RefreshSeconds As Double = 0.2

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _traced As Action(Of String, String())
    Private ReadOnly _show As New ScaledCheckBox With {.Text = "Draw the forces on the canvas", .UseMnemonic = False}
    Private ReadOnly _bodyLabel As New Label With {.Text = "Body", .UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private ReadOnly _body As New OneLineComboBox()
    Private ReadOnly _list As New ListView With {.View = View.Details, .FullRowSelect = True, .GridLines = True}
    Private ReadOnly _sum As New Label With {.UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private ReadOnly _air As New ScaledCheckBox With {.Text = "Air", .UseMnemonic = False}
    Private ReadOnly _densityLabel As New Label With {.Text = "ρ (kg/m²)", .UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private ReadOnly _density As New TextBox With {.Text = Units.Input(SimulationPresenter.DefaultAirDensity)}
    Private ReadOnly _setAir As New Button With {.Text = "Set air", .UseMnemonic = False}
    Private ReadOnly _cdLabel As New Label With {.Text = "C_d", .UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private ReadOnly _cd As New TextBox()
    Private ReadOnly _bLabel As New Label With {.Text = "b (N·s/m)", .UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private ReadOnly _b As New TextBox()
    Private ReadOnly _setDrag As New Button With {.Text = "Set drag", .UseMnemonic = False}
    Private ReadOnly _note As New Label With {.Text = SimulationPresenter.DragNote, .UseMnemonic = False}
    ''' <summary>The air's density (kg/m²) the air row last showed; NaN: not yet.</summary>
    Private _shownAir As Double = Double.NaN
    ''' <summary>The body and its C_d and b the drag boxes last showed.</summary>
    Private _shownDrag As (Id As String, Cd As Double, B As Double)
    Private _refreshedAt As Double = -1
    Private _filling As Boolean

    ''' <param name="traced">writes what the page shows to the trace, when it changed (the window's)</param>
    Public Sub New(kit As WindowKit, traced As Action(Of String, String()))
        _kit = kit
        _traced = traced
        ' Check boxes whose box, and text boxes and a drop-down whose height, grow with the text, as the side panel's.
        _show.ScreenScale = kit.Dpi.Scale
        _air.ScreenScale = kit.Dpi.Scale
        For Each box In {(_density, "forces-air-density"), (_cd, "forces-cd"), (_b, "forces-b")}
            WindowKit.KeepToOneLine(box.Item1, kit.Trace, box.Item2)
        Next
        For Each h In FreeBodyView.Headers
            _list.Columns.Add(h, 100)
        Next
        _kit.Tips.SetToolTip(_show, "Arrows for every force on the body chosen here: weight, normal forces, friction, tensions, springs, drag and upthrust")
        AddHandler _show.CheckedChanged, Sub(s, e) _kit.Act(Sub() _kit.Presenter.SetShowForces(_show.Checked))
        AddHandler _body.SelectedIndexChanged,
            Sub(s, e)
                If _filling OrElse _body.SelectedItem Is Nothing Then Return
                Dim id = CStr(_body.SelectedItem)
                _kit.Act(Sub() _kit.Presenter.ChooseForcesBody(id))
                Fill()
            End Sub
        Dim airTip = "Air on or off, with its density ρ in kg/m² (areal, like every density in this 2D world; " & Units.Input(SimulationPresenter.DefaultAirDensity) & " when nothing is typed). Enter or ""Set air"" applies it."
        For Each c In New Control() {_air, _densityLabel, _density, _setAir}
            _kit.Tips.SetToolTip(c, airTip)
        Next
        For Each c In New Control() {_cdLabel, _cd, _bLabel, _b, _setDrag, _note}
            _kit.Tips.SetToolTip(c, "The drag of the body chosen above. " & SimulationPresenter.DragNote & " Enter or ""Set drag"" applies it.")
        Next
        AddHandler _air.CheckedChanged, Sub(s, e) If Not _filling Then ApplyAir(_air.Checked)
        AddHandler _setAir.Click, Sub(s, e) ApplyAir(True)
        AddHandler _setDrag.Click, Sub(s, e) ApplyDrag()
        OnEnter(_density, Sub() ApplyAir(True))
        OnEnter(_cd, AddressOf ApplyDrag)
        OnEnter(_b, AddressOf ApplyDrag)
        Page.Controls.AddRange(New Control() {_show, _bodyLabel, _body, _list, _sum})
        Page.Controls.AddRange(AirControls())
        AddHandler Page.Resize, Sub(s, e) Arrange()
    End Sub

    ''' <summary>The tab page.</summary>
    Public ReadOnly Property Page As New TabPage(FreeBodyView.Title) With {.AutoScroll = True}

    ''' <summary>The page's controls in the theme's colours (their font is the window's: they take it from it, never a copy a font change would dispose of).</summary>
    Public Sub Restyle()
        Dim theme = _kit.Presenter.Theme
        For Each c In New Control() {_show, _bodyLabel, _body, _list, _sum, _air, _densityLabel, _cdLabel, _bLabel, _note}
            c.ForeColor = ScenePainter.Rgb(theme.PanelText)
            c.BackColor = ScenePainter.Rgb(theme.Panel)
        Next
        For Each b In {_setAir, _setDrag}
            WindowKit.Style(b, theme)
        Next
        Arrange()
    End Sub

    ''' <summary>The box on the first row, the body's chooser on the second, the list under them, ΣF and m a, then the air and drag rows (each wrapping when narrow) at the bottom.</summary>
    Public Sub Arrange()
        If _kit.Presenter Is Nothing Then Return
        Dim w = Page.ClientSize.Width, h = Page.ClientSize.Height
        Dim total = LayOut(w, h)
        ' Too short for all of it (large fonts on a small screen): the page scrolls, and its contents leave room
        ' for the scroll bar rather than spill under it and scroll sideways too (Mono's client size keeps the bar's width).
        If total > h Then total = LayOut(w - SystemInformation.VerticalScrollBarWidth - _kit.S(2), h)
        Dim needed = New Size(0, If(total > h, total, 0))
        If Page.AutoScrollMinSize <> needed Then Page.AutoScrollMinSize = needed
    End Sub

    ''' <summary>Lays the page out <paramref name="w"/> px wide, shifted by how far it is scrolled; returns the height it takes, px.</summary>
    Private Function LayOut(w As Integer, h As Integer) As Integer
        Dim rh = _kit.ButtonRowHeight()
        Dim oy = Page.AutoScrollPosition.Y
        Dim x = _kit.S(4), y = _kit.S(3)
        Dim labelWidth = _kit.Measure(_bodyLabel.Text, _kit.Font).Width + _kit.S(8)
        _show.SetBounds(x, y + oy, Math.Max(1, _kit.Measure(_show.Text, _kit.Font).Width + _kit.S(28)), rh)
        Dim bodyX = _show.Right + _kit.S(12)
        If bodyX + labelWidth + _kit.S(120) > w Then
            bodyX = x
            y += rh + _kit.S(4)
        End If
        _bodyLabel.SetBounds(bodyX, y + oy, labelWidth, rh)
        ' The drop-down a line of text and a margin high, in the middle of its row; its items a line high.
        Dim itemHeight = _kit.LineHeight(_kit.Font) + _kit.S(4)
        If _body.ItemHeight <> itemHeight Then _body.ItemHeight = itemHeight
        Dim boxHeight = Math.Min(rh, _kit.OneLineHeight(_kit.Font))
        _body.SetBounds(bodyX + labelWidth, y + (rh - boxHeight) \ 2 + oy, Math.Max(_kit.S(120), Math.Min(_kit.S(220), w - bodyX - labelWidth - _kit.S(4))), boxHeight)
        Dim top = y + rh + _kit.S(4)
        Dim sumHeight = _kit.LineHeight(_kit.Font) + _kit.S(6)
        ' The air and drag rows, laid out from the top to learn their height, then moved to the bottom; the list
        ' keeps room for its header and two forces.
        Dim rowsHeight = FlowRows(x, 0, w, rh)
        Dim leastList = 3 * (_kit.LineHeight(_list.Font) + _kit.S(4))
        Dim listHeight = Math.Max(leastList, h - top - sumHeight - rowsHeight)
        Dim rowsTop = top + listHeight + sumHeight
        FlowRows(x, rowsTop + oy, w, rh)
        _list.SetBounds(0, top + oy, Math.Max(1, w), listHeight)
        _sum.SetBounds(x, rowsTop - sumHeight + oy, Math.Max(1, w - 2 * x), sumHeight)
        Dim columnWidth = Math.Max(_kit.S(60), (w - _kit.S(24)) \ Math.Max(1, _list.Columns.Count))
        For Each c As ColumnHeader In _list.Columns
            c.Width = columnWidth
        Next
        For Each b In Page.Controls.OfType(Of Button)()
            _kit.CentreCaption(b)
        Next
        Return rowsTop + rowsHeight
    End Function

    ''' <summary>The air row's and the drag row's controls, in the order they are laid out.</summary>
    Private Function AirControls() As Control()
        Return New Control() {_air, _densityLabel, _density, _setAir, _cdLabel, _cd, _bLabel, _b, _setDrag, _note}
    End Function

    ''' <summary>
    ''' Lays out "[x] Air  ρ (kg/m²) [1.2] [Set air]", "C_d [..] b (N·s/m) [..] [Set drag]" and the note from
    ''' <paramref name="top"/>, the drag group beside the air group when both fit, any piece on the next line when it would pass the right edge; returns the height used, px.
    ''' </summary>
    Private Function FlowRows(left As Integer, top As Integer, width As Integer, rh As Integer) As Integer
        Dim gap = _kit.S(4)
        Dim boxWidth = Math.Max(_kit.S(56), _kit.Measure("0.0000", _kit.Font).Width + _kit.S(12))
        Dim y = top, px = left
        ' The drag group goes beside the air group when both fit on one line, so the list keeps its room.
        For Each pieces In {New Control() {_air, _densityLabel, _density, _setAir}, New Control() {_cdLabel, _cd, _bLabel, _b, _setDrag}}
            Dim widths = pieces.Select(Function(c) PieceWidth(c, boxWidth)).ToArray()
            If px > left AndAlso px + _kit.S(12) + widths.Sum() + gap * (widths.Length - 1) > width - gap Then
                px = left
                y += rh + gap
            ElseIf px > left Then
                px += _kit.S(12)
            End If
            For i = 0 To pieces.Length - 1
                If px > left AndAlso px + widths(i) > width - gap Then
                    px = left
                    y += rh + gap
                End If
                ' A text box is a line of text and a margin high, in the middle of the row.
                Dim h = If(TypeOf pieces(i) Is TextBox, Math.Min(rh, _kit.OneLineHeight(_kit.Font)), rh)
                pieces(i).SetBounds(px, y + (rh - h) \ 2, widths(i), h)
                px += widths(i) + gap
            Next
        Next
        y += rh + gap
        Dim noteWidth = Math.Max(1, width - 2 * left)
        Dim noteHeight = _kit.Measure(_note.Text, _kit.Font, noteWidth).Height + _kit.S(2)
        _note.SetBounds(left, y, noteWidth, noteHeight)
        Return y + noteHeight + gap - top
    End Function

    ''' <summary>The width of one piece of the air and drag rows: its text and the room a box, check or button edge takes, px.</summary>
    Private Function PieceWidth(c As Control, boxWidth As Integer) As Integer
        If TypeOf c Is TextBox Then Return boxWidth
        If TypeOf c Is CheckBox Then Return _kit.Measure(c.Text, _kit.Font).Width + _kit.S(28)
        If TypeOf c Is Button Then Return _kit.Measure(c.Text, _kit.Font).Width + _kit.S(20)
        Return _kit.Measure(c.Text, _kit.Font).Width + _kit.S(12)
    End Function

    ''' <summary>Enter in <paramref name="box"/> does <paramref name="apply"/> (and no beep).</summary>
    Private Shared Sub OnEnter(box As TextBox, apply As Action)
        AddHandler box.KeyDown,
            Sub(s, e)
                If e.KeyCode <> Keys.Enter AndAlso e.KeyCode <> Keys.Return Then Return
                e.Handled = True
                e.SuppressKeyPress = True
                apply()
            End Sub
    End Sub

    ''' <summary>Air on (the check box ticked, or the density applied) or off (unticked) with the typed density; the row then shows what the world has (what was typed stays when refused).</summary>
    Private Sub ApplyAir(airOn As Boolean)
        _kit.Act(Sub() _kit.Presenter.SetAir(airOn, _density.Text))
        ShowAir(force:=True)
    End Sub

    ''' <summary>The chosen body's drag from the typed C_d and b; the boxes then show what it has (what was typed stays when refused).</summary>
    Private Sub ApplyDrag()
        Dim id = CStr(_body.SelectedItem)
        If id Is Nothing Then
            Dim d = _kit.Presenter.ForcesDiagram()
            id = If(d Is Nothing, "", d.Body.Id)
        End If
        _kit.Act(Sub() _kit.Presenter.SetDrag(id, _cd.Text, _b.Text))
        ShowDrag(id, force:=True)
    End Sub

    ''' <summary>The air row shows the world's air when it changed since it last did (a scene opened, Reset), or when <paramref name="force"/>d (the check box always).</summary>
    Private Sub ShowAir(force As Boolean)
        Dim air = _kit.Presenter.AirDensity
        Dim changed = Not air.Equals(_shownAir)
        _filling = True
        Try
            _air.Checked = air > 0
        Finally
            _filling = False
        End Try
        If changed AndAlso air > 0 Then _density.Text = Units.Input(air)
        _shownAir = air
        If changed OrElse force Then _traced("air row", {_air.Checked.ToString(Globalization.CultureInfo.InvariantCulture), _density.Text})
    End Sub

    ''' <summary>The drag boxes show the body <paramref name="id"/>'s C_d and b when the body or its values changed since they last did (what is being typed is left alone otherwise).</summary>
    Private Sub ShowDrag(id As String, force As Boolean)
        Dim drag = _kit.Presenter.DragOf(id)
        If Not drag.HasValue Then
            _cd.Enabled = False
            _b.Enabled = False
            _setDrag.Enabled = False
            Return
        End If
        _cd.Enabled = True
        _b.Enabled = True
        _setDrag.Enabled = True
        Dim now = (Id:=id, Cd:=drag.Value.DragCoefficient, B:=drag.Value.LinearDrag)
        Dim changed = now.Id <> _shownDrag.Id OrElse Not now.Cd.Equals(_shownDrag.Cd) OrElse Not now.B.Equals(_shownDrag.B)
        If changed Then
            _cd.Text = Units.Input(now.Cd)
            _b.Text = Units.Input(now.B)
            _shownDrag = now
        End If
        If changed OrElse force Then _traced("drag row", {id, _cd.Text, _b.Text})
    End Sub

    ''' <summary>The page's controls, by the names the --trace layout gives them (only while it is on show).</summary>
    Public Function Controls(onShow As Boolean) As IEnumerable(Of (Name As String, Control As Control))
        Dim named As New List(Of (Name As String, Control As Control))
        If Not onShow Then Return named
        named.Add(("forces-show", _show))
        named.Add(("forces-body", _body))
        named.Add(("forces-list", _list))
        named.Add(("forces-sum", _sum))
        named.Add(("forces-air", _air))
        named.Add(("forces-air-density-label", _densityLabel))
        named.Add(("forces-air-density", _density))
        named.Add(("forces-set-air", _setAir))
        named.Add(("forces-cd-label", _cdLabel))
        named.Add(("forces-cd", _cd))
        named.Add(("forces-b-label", _bLabel))
        named.Add(("forces-b", _b))
        named.Add(("forces-set-drag", _setDrag))
        Return named
    End Function

    ''' <summary>While the page is on show (<paramref name="onShow"/>), refreshes the list a few times a second.</summary>
    Public Sub Refresh(now As Double, onShow As Boolean)
        If Not onShow OrElse now - _refreshedAt < RefreshSeconds Then Return
        _refreshedAt = now
        Fill()
    End Sub

    ''' <summary>The bodies to choose from, the forces on the one shown and ΣF beside m a, from the presenter now.</summary>
    Private Sub Fill()
        Dim p = _kit.Presenter
        If p Is Nothing Then Return
        If _show.Checked <> p.Forces.Shown Then _show.Checked = p.Forces.Shown
        Dim ids = p.ForcesBodies()
        Dim d = p.ForcesDiagram()
        _filling = True
        Try
            If Not ids.SequenceEqual(_body.Items.Cast(Of String)()) Then
                _body.Items.Clear()
                For Each id In ids
                    _body.Items.Add(id)
                Next
            End If
            Dim shownId = If(d Is Nothing, Nothing, d.Body.Id)
            If shownId IsNot Nothing AndAlso CStr(_body.SelectedItem) <> shownId Then _body.SelectedItem = shownId
        Finally
            _filling = False
        End Try
        Dim rows = FreeBodyView.Rows(d)
        _list.BeginUpdate()
        _list.Items.Clear()
        For Each r In rows
            _list.Items.Add(New ListViewItem(r))
        Next
        _list.EndUpdate()
        _sum.Text = FreeBodyView.SumLine(d)
        ShowAir(force:=False)
        ShowDrag(If(d Is Nothing, "", d.Body.Id), force:=False)
        _traced("forces tab", rows.Select(Function(r) String.Join(" ", r)).Concat({_sum.Text}).ToArray())
    End Sub

    ''' <summary>The page, and its controls with it.</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        Page.Dispose()
    End Sub
End Class
