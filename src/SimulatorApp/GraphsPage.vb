Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The Graphs tab: a row of buttons choosing the graph, the gas controls beside them, the graph drawn
''' by GraphPainter, and the graph in a window of its own for a projector. What the graph shows and
''' what the gas controls do is the presenter's (its GraphRecorder and GasControls).
''' </summary>
Friend NotInheritable Class GraphsPage
    Implements IDisposable

    ''' <summary>Real time between redraws of the graph while time runs, s.</summary>
    Private Const GraphSeconds As Double = 0.1

    ''' <summary>The graph buttons' captions and trace names, in <see cref="GraphKind"/> order.</summary>
    Private Shared ReadOnly GraphButtons As (Caption As String, Name As String)() = {
        ("Energy", "graph-energy"), ("Momentum", "graph-momentum"), ("Speeds", "graph-speeds"), ("Pressure", "graph-pressure")}

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _box As New PictureBox()
    Private ReadOnly _graphButtons As New List(Of Button)
    Private ReadOnly _windowButton As New Button()
    Private ReadOnly _gasButtons As New List(Of (Button As Button, Name As String))
    Private _window As GraphWindow
    Private _drawnAt As Double = -1
    Private ReadOnly _traced As Action(Of String, String())

    ''' <param name="traced">writes what a list or the graph shows to the trace, when it changed (the window's)</param>
    Public Sub New(kit As WindowKit, traced As Action(Of String, String()))
        _kit = kit
        _traced = traced
        For i = 0 To GraphButtons.Length - 1
            Dim kind = CType(i, GraphKind)
            Dim b As New Button With {.Text = GraphButtons(i).Caption, .UseMnemonic = False}
            _kit.Tips.SetToolTip(b, SimulationPresenter.GraphNames(i))
            AddHandler b.Click,
                Sub(s, e)
                    _kit.Presenter.ChooseGraph(kind)
                    ColourButtons()
                    Redraw()
                End Sub
            _graphButtons.Add(b)
            Page.Controls.Add(b)
        Next
        Dim factor = SimulationPresenter.HeatFactor.ToString(Globalization.CultureInfo.InvariantCulture)
        ' Short captions, so the gas controls share the graph buttons' row: their tips say what they do.
        For Each gas In {("Heat ▲", "gas-heat", "Heat the gas: every speed × √" & factor & ", so kT = mean KE × " & factor, CType(Sub() _kit.Presenter.Heat(), Action)),
                         ("Cool ▼", "gas-cool", "Cool the gas: kT = mean KE ÷ " & factor, CType(Sub() _kit.Presenter.Cool(), Action)),
                         ("+" & SimulationPresenter.GasStep, "gas-add", "Add " & SimulationPresenter.GasStep & " balls like the gas's, at its temperature", CType(Sub() _kit.Presenter.AddBalls(), Action)),
                         ("−" & SimulationPresenter.GasStep, "gas-remove", "Remove " & SimulationPresenter.GasStep & " balls at random", CType(Sub() _kit.Presenter.RemoveBalls(), Action))}
            Dim action = gas.Item4
            Dim b As New Button With {.Text = gas.Item1, .UseMnemonic = False}
            _kit.Tips.SetToolTip(b, gas.Item3)
            AddHandler b.Click,
                Sub(s, e)
                    _kit.Act(action)
                    Redraw()
                End Sub
            _gasButtons.Add((b, gas.Item2))
            Page.Controls.Add(b)
        Next
        _windowButton.Text = WindowCaption
        _windowButton.UseMnemonic = False
        _kit.Tips.SetToolTip(_windowButton, "The graph in a window of its own, large enough for a projector")
        AddHandler _windowButton.Click, Sub(s, e) ShowWindow()
        Page.Controls.Add(_windowButton)
        AddHandler _box.Paint, AddressOf OnPaint
        Page.Controls.Add(_box)
        AddHandler Page.Resize, Sub(s, e) Arrange()
    End Sub

    ''' <summary>The window button's caption when there is room for it.</summary>
    Private Const WindowCaption As String = "⤢ Window"

    ''' <summary>The tab page.</summary>
    Public ReadOnly Property Page As New TabPage("Graphs")

    ''' <summary>Draws the graph again, on the page and in its window.</summary>
    Private Sub Redraw()
        _box.Invalidate()
        _window?.Redraw()
    End Sub

    ''' <summary>
    ''' The page's buttons in the theme's colours (their font is the window's: they take it from it,
    ''' never hold a copy a font change would dispose of while the page is laid out); the graph's
    ''' window follows the font.
    ''' </summary>
    Public Sub Restyle()
        Dim theme = _kit.Presenter.Theme
        For Each b In _graphButtons.Concat({_windowButton}).Concat(_gasButtons.Select(Function(g) g.Button))
            WindowKit.Style(b, theme)
        Next
        If _window IsNot Nothing Then
            _window.Font = _kit.Font
            _window.Redraw()
        End If
        ColourButtons()
        Arrange()
    End Sub

    ''' <summary>The button of the graph on show is lit like a tool in use.</summary>
    Private Sub ColourButtons()
        Dim p = _kit.Presenter
        Dim theme = p.Theme
        For i = 0 To _graphButtons.Count - 1
            _graphButtons(i).BackColor = ScenePainter.Rgb(If(i = CInt(p.Graph), theme.MessageBack, theme.Button))
            _graphButtons(i).ForeColor = ScenePainter.Rgb(If(i = CInt(p.Graph), theme.MessageText, theme.PanelText))
        Next
    End Sub

    ''' <summary>
    ''' The graph buttons in a row at the top of the page, then the gas controls, then the window
    ''' button at the right end; a second row when they do not fit in one. The graph under them.
    ''' </summary>
    Public Sub Arrange()
        If _kit.Presenter Is Nothing Then Return
        Dim w = Page.ClientSize.Width, h = Page.ClientSize.Height
        Dim rh = _kit.ButtonRowHeight()
        Dim x = _kit.S(4), y = _kit.S(3)
        Dim widthOf = Function(b As Button) Math.Max(_kit.S(44), _kit.Measure(b.Text, _kit.Font).Width + _kit.S(18))
        For Each b In _graphButtons
            b.SetBounds(x, y, widthOf(b), rh)
            x += b.Width + _kit.S(6)
        Next
        ' One row when it all fits (the window button as just ⤢ when that is what makes it fit, its tip says the rest).
        _windowButton.Text = WindowCaption
        Dim gasWidth = _gasButtons.Sum(Function(g) widthOf(g.Button) + _kit.S(6)) + widthOf(_windowButton) + _kit.S(12)
        If x + gasWidth > w Then
            _windowButton.Text = "⤢"
            gasWidth = _gasButtons.Sum(Function(g) widthOf(g.Button) + _kit.S(6)) + widthOf(_windowButton) + _kit.S(12)
        End If
        If x + gasWidth > w Then
            x = _kit.S(4)
            y += rh + _kit.S(4)
        Else
            x += _kit.S(12)
        End If
        For Each g In _gasButtons
            g.Button.SetBounds(x, y, widthOf(g.Button), rh)
            x += g.Button.Width + _kit.S(6)
        Next
        ' The window button at the right end of the row.
        Dim ww = widthOf(_windowButton)
        _windowButton.SetBounds(Math.Max(x + _kit.S(6), w - ww - _kit.S(4)), y, ww, rh)
        For Each b In Page.Controls.OfType(Of Button)()
            _kit.CentreCaption(b)
        Next
        Dim top = y + rh + _kit.S(4)
        _box.SetBounds(0, top, Math.Max(1, w), Math.Max(1, h - top))
        _box.Invalidate()
    End Sub

    ''' <summary>The page's controls, by the names the --trace layout gives them (only while the page is on show: a hidden page has no place on the screen).</summary>
    Public Function Controls(onShow As Boolean) As IEnumerable(Of (Name As String, Control As Control))
        Dim named As New List(Of (Name As String, Control As Control))
        If Not onShow Then Return named
        For i = 0 To _graphButtons.Count - 1
            named.Add((GraphButtons(i).Name, _graphButtons(i)))
        Next
        named.Add(("graph-window", _windowButton))
        For Each g In _gasButtons
            named.Add((g.Name, CType(g.Button, Control)))
        Next
        named.Add(("graph", _box))
        Return named
    End Function

    ''' <summary>While the page (<paramref name="onShow"/>) or the graph's window is on show, redraws the graph about ten times a second.</summary>
    Public Sub Refresh(now As Double, onShow As Boolean)
        If Not onShow AndAlso _window Is Nothing Then Return
        If now - _drawnAt < GraphSeconds Then Return
        _drawnAt = now
        If onShow Then _box.Invalidate()
        _window?.Redraw()
    End Sub

    ''' <summary>Opens the graph in a window of its own (or brings it to the front), over most of the screen.</summary>
    Private Sub ShowWindow()
        If _window Is Nothing Then
            Dim area = Screen.FromControl(_kit.Window).WorkingArea
            Dim bounds = New Drawing.Rectangle(area.X + area.Width \ 10, area.Y + area.Height \ 10, area.Width * 8 \ 10, area.Height * 8 \ 10)
            _window = New GraphWindow(_kit.Presenter, _kit.Font, _kit.Dpi.Scale, bounds)
            AddHandler _window.FormClosed,
                Sub(s, e)
                    _window.Dispose()
                    _window = Nothing
                    _kit.Emit("graph window closed")
                End Sub
            AddHandler _window.Shown,
                Sub(s, e)
                    Dim r = _window.GraphBounds
                    _kit.Emit("graph window shown " & r.X & " " & r.Y & " " & r.Width & " " & r.Height)
                End Sub
            _window.Show(_kit.Window)
        Else
            _window.Activate()
        End If
        _window.Redraw()
    End Sub

    Private Sub OnPaint(sender As Object, e As PaintEventArgs)
        Dim p = _kit.Presenter
        Dim start = Diagnostics.Stopwatch.GetTimestamp()
        Dim plot = p.CurrentGraph()
        GraphPainter.Paint(e.Graphics, plot, p.Theme, _kit.Font, _box.ClientSize.Width, _box.ClientSize.Height, _kit.Dpi.Scale)
        ' Drawn ten times a second, in some frame: the budget leaves room for it there (see FrameBudget).
        p.NoteFrameWork((Diagnostics.Stopwatch.GetTimestamp() - start) / CDbl(Diagnostics.Stopwatch.Frequency))
        TraceGraph(plot)
    End Sub

    ''' <summary>
    ''' With --trace: what the graph shows when it changes: its kind, points per curve, and for the
    ''' histogram the total of its bars and each bar's count (GUI tests read these).
    ''' </summary>
    Private Sub TraceGraph(plot As GraphPlot)
        If _kit.Trace Is Nothing Then Return
        Dim cells As New List(Of String) From {_kit.Presenter.Graph.ToString()}
        cells.AddRange(plot.Lines.Select(Function(l) l.Name))
        If plot.Bars IsNot Nothing Then
            cells.Add("total " & plot.Bars.Total)
            cells.Add("bin " & plot.Bars.BinWidth.ToString("R", Globalization.CultureInfo.InvariantCulture))
            cells.Add("counts " & String.Join(" ", plot.Bars.Counts))
        End If
        cells.AddRange(plot.Notes)
        _traced("graph", cells.ToArray())
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _window?.Dispose()
    End Sub
End Class
