Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The Forces tab: a box that draws the free-body diagram on the canvas, the body it is of, the forces on it
''' (kind, what exerts it, size in N, direction in degrees) and ΣF beside m a. What is shown is the presenter's
''' (its <see cref="FreeBodyView"/>); this only lays it out and refreshes it a few times a second.
''' </summary>
Friend NotInheritable Class ForcesPage
    Implements IDisposable

    ''' <summary>Real time between refreshes of the list while the page is on show, s.</summary>
    Private Const RefreshSeconds As Double = 0.2

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _traced As Action(Of String, String())
    Private ReadOnly _show As New CheckBox With {.Text = "Draw the forces on the canvas", .UseMnemonic = False}
    Private ReadOnly _bodyLabel As New Label With {.Text = "Body", .UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private ReadOnly _body As New ComboBox With {.DropDownStyle = ComboBoxStyle.DropDownList}
    Private ReadOnly _list As New ListView With {.View = View.Details, .FullRowSelect = True, .GridLines = True}
    Private ReadOnly _sum As New Label With {.UseMnemonic = False, .TextAlign = ContentAlignment.MiddleLeft}
    Private _refreshedAt As Double = -1
    Private _filling As Boolean

    ''' <param name="traced">writes what the page shows to the trace, when it changed (the window's)</param>
    Public Sub New(kit As WindowKit, traced As Action(Of String, String()))
        _kit = kit
        _traced = traced
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
        Page.Controls.AddRange(New Control() {_show, _bodyLabel, _body, _list, _sum})
        AddHandler Page.Resize, Sub(s, e) Arrange()
    End Sub

    ''' <summary>The tab page.</summary>
    Public ReadOnly Property Page As New TabPage(FreeBodyView.Title)

    ''' <summary>The page's controls in the theme's colours (their font is the window's: they take it from it, never a copy a font change would dispose of).</summary>
    Public Sub Restyle()
        Dim theme = _kit.Presenter.Theme
        For Each c In New Control() {_show, _bodyLabel, _body, _list, _sum}
            c.ForeColor = ScenePainter.Rgb(theme.PanelText)
            c.BackColor = ScenePainter.Rgb(theme.Panel)
        Next
        Arrange()
    End Sub

    ''' <summary>The box on the first row, the body's chooser on the second, the list under them, ΣF and m a at the bottom.</summary>
    Public Sub Arrange()
        If _kit.Presenter Is Nothing Then Return
        Dim w = Page.ClientSize.Width, h = Page.ClientSize.Height
        Dim rh = _kit.ButtonRowHeight()
        Dim x = _kit.S(4), y = _kit.S(3)
        Dim labelWidth = _kit.Measure(_bodyLabel.Text, _kit.Font).Width + _kit.S(8)
        _show.SetBounds(x, y, Math.Max(1, _kit.Measure(_show.Text, _kit.Font).Width + _kit.S(28)), rh)
        Dim bodyX = _show.Right + _kit.S(12)
        If bodyX + labelWidth + _kit.S(120) > w Then
            bodyX = x
            y += rh + _kit.S(4)
        End If
        _bodyLabel.SetBounds(bodyX, y, labelWidth, rh)
        _body.SetBounds(bodyX + labelWidth, y, Math.Max(_kit.S(120), Math.Min(_kit.S(220), w - bodyX - labelWidth - _kit.S(4))), rh)
        Dim top = y + rh + _kit.S(4)
        Dim sumHeight = _kit.LineHeight(_kit.Font) + _kit.S(6)
        _list.SetBounds(0, top, Math.Max(1, w), Math.Max(1, h - top - sumHeight))
        _sum.SetBounds(x, h - sumHeight, Math.Max(1, w - 2 * x), sumHeight)
        Dim columnWidth = Math.Max(_kit.S(60), (w - _kit.S(24)) \ Math.Max(1, _list.Columns.Count))
        For Each c As ColumnHeader In _list.Columns
            c.Width = columnWidth
        Next
    End Sub

    ''' <summary>The page's controls, by the names the --trace layout gives them (only while it is on show).</summary>
    Public Function Controls(onShow As Boolean) As IEnumerable(Of (Name As String, Control As Control))
        Dim named As New List(Of (Name As String, Control As Control))
        If Not onShow Then Return named
        named.Add(("forces-show", _show))
        named.Add(("forces-body", _body))
        named.Add(("forces-list", _list))
        named.Add(("forces-sum", _sum))
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
        _traced("forces tab", rows.Select(Function(r) String.Join(" ", r)).Concat({_sum.Text}).ToArray())
    End Sub

    ''' <summary>The page, and its controls with it.</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        Page.Dispose()
    End Sub
End Class
