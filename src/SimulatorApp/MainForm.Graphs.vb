Option Strict On
Imports System.Drawing
Imports System.Drawing.Imaging
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' The Graphs tab (a row of buttons choosing the graph, and the graph drawn by GraphPainter) and the
' Export menu (CSV of the tables and series, PNG of the graph and the canvas). What they show and
' write is the presenter's (SimulationPresenter.Graphs and .Export).
Partial Friend NotInheritable Class MainForm
    ''' <summary>Real time between redraws of the graph while time runs, s.</summary>
    Private Const GraphSeconds As Double = 0.1

    Private ReadOnly _graphPage As New TabPage("Graphs")
    Private ReadOnly _graphBox As New PictureBox()
    Private ReadOnly _graphButtons As New List(Of Button)
    Private ReadOnly _graphWindowButton As New Button()
    ''' <summary>The gas controls beside the graph buttons: heat, cool, balls added and removed.</summary>
    Private ReadOnly _gasButtons As New List(Of (Button As Button, Name As String))
    Private _graphWindow As GraphWindow
    Private ReadOnly _export As New Button()
    Private ReadOnly _exportMenu As New ContextMenuStrip()
    Private ReadOnly _solver As New Button()
    Private ReadOnly _solverMenu As New ContextMenuStrip()
    Private _graphDrawnAt As Double = -1

    ''' <summary>The exported graph picture's size at 96 dpi, px (twice as many on a 192-dpi screen).</summary>
    Friend Shared ReadOnly GraphPictureSize As New Size(1280, 720)

    ''' <summary>The graph buttons' captions and trace names, in <see cref="GraphKind"/> order.</summary>
    Private Shared ReadOnly GraphButtons As (Caption As String, Name As String)() = {
        ("Energy", "graph-energy"), ("Momentum", "graph-momentum"), ("Speeds", "graph-speeds"), ("Pressure", "graph-pressure")}

    Private Sub BuildGraphControls()
        For i = 0 To GraphButtons.Length - 1
            Dim kind = CType(i, GraphKind)
            Dim b As New Button With {.Text = GraphButtons(i).Caption, .UseMnemonic = False}
            _tips.SetToolTip(b, SimulationPresenter.GraphNames(i))
            AddHandler b.Click,
                Sub(s, e)
                    _presenter.ChooseGraph(kind)
                    ColourGraphButtons()
                    _graphBox.Invalidate()
                    _graphWindow?.Redraw()
                End Sub
            _graphButtons.Add(b)
            _graphPage.Controls.Add(b)
        Next
        For Each gas In {("Heat ▲", "gas-heat", "Heat the gas: every speed × √" & SimulationPresenter.HeatFactor.ToString(Globalization.CultureInfo.InvariantCulture) & ", so kT = mean KE × " & SimulationPresenter.HeatFactor.ToString(Globalization.CultureInfo.InvariantCulture), CType(Sub() _presenter.Heat(), Action)),
                         ("Cool ▼", "gas-cool", "Cool the gas: kT = mean KE ÷ " & SimulationPresenter.HeatFactor.ToString(Globalization.CultureInfo.InvariantCulture), CType(Sub() _presenter.Cool(), Action)),
                         ("+" & SimulationPresenter.GasStep & " balls", "gas-add", "Add balls like the gas's, at its temperature", CType(Sub() _presenter.AddBalls(), Action)),
                         ("−" & SimulationPresenter.GasStep & " balls", "gas-remove", "Remove balls at random", CType(Sub() _presenter.RemoveBalls(), Action))}
            Dim action = gas.Item4
            Dim b As New Button With {.Text = gas.Item1, .UseMnemonic = False}
            _tips.SetToolTip(b, gas.Item3)
            AddHandler b.Click,
                Sub(s, e)
                    Act(action)
                    _graphBox.Invalidate()
                    _graphWindow?.Redraw()
                End Sub
            _gasButtons.Add((b, gas.Item2))
            _graphPage.Controls.Add(b)
        Next
        _graphWindowButton.Text = "⤢ Window"
        _graphWindowButton.UseMnemonic = False
        _tips.SetToolTip(_graphWindowButton, "The graph in a window of its own, large enough for a projector")
        AddHandler _graphWindowButton.Click, Sub(s, e) ShowGraphWindow()
        _graphPage.Controls.Add(_graphWindowButton)
        AddHandler _graphBox.Paint, AddressOf OnGraphPaint
        _graphPage.Controls.Add(_graphBox)
        AddHandler _graphPage.Resize, Sub(s, e) ArrangeGraphPage()
        _tabs.TabPages.Add(_graphPage)
        AddHeaderButton(_export, SimulationPresenter.ExportCaption, AddressOf ShowExportMenu)
        _tips.SetToolTip(_export, "Save the tables, the collision log or the graph as CSV, or the graph or the canvas as a picture")
        AddHandler _exportMenu.Closed, Sub(s, e) _trace?.Invoke("export menu closed")
        AddHeaderButton(_solver, "Solver ▾", AddressOf ShowSolverMenu)
        _tips.SetToolTip(_solver, "How the scene is moved on in time: choose another, then Restart, to compare")
        AddHandler _solverMenu.Closed, Sub(s, e) _trace?.Invoke("solver menu closed")
    End Sub

    ''' <summary>Export left of Scenes on the tabs' header row, as tall as it; the graph page laid out and coloured.</summary>
    Private Sub PlaceGraphControls()
        Dim width = Math.Max(S(90), Measure(_export.Text, Font).Width + S(24))
        _export.SetBounds(_scenes.Left - S(6) - width, _scenes.Top, width, _scenes.Height)
        _export.BringToFront()
        ' The solver's button left of Export, as wide as its caption ("Solver: Verlet (fixed step) ▾").
        Dim solverWidth = Math.Max(S(90), SolverCaptions().Max(Function(c) Measure(c, Font).Width) + S(24))
        _solver.SetBounds(_export.Left - S(6) - solverWidth, _export.Top, solverWidth, _export.Height)
        _solver.BringToFront()
        Dim theme = _presenter.Theme
        For Each b In _graphButtons.Concat({_export, _graphWindowButton, _solver}).Concat(_gasButtons.Select(Function(g) g.Button))
            b.Font = Font
            b.ForeColor = ScenePainter.Rgb(theme.PanelText)
            b.FlatStyle = If(theme.IsHighContrast, FlatStyle.Flat, FlatStyle.Standard)
            b.FlatAppearance.BorderColor = ScenePainter.Rgb(theme.PanelText)
            b.FlatAppearance.BorderSize = If(theme.IsHighContrast, 2, 1)
            b.UseVisualStyleBackColor = Not theme.IsHighContrast
        Next
        _export.BackColor = ScenePainter.Rgb(theme.Button)
        _solver.BackColor = ScenePainter.Rgb(theme.Button)
        _graphWindowButton.BackColor = ScenePainter.Rgb(theme.Button)
        For Each g In _gasButtons
            g.Button.BackColor = ScenePainter.Rgb(theme.Button)
        Next
        If _graphWindow IsNot Nothing Then
            _graphWindow.Font = Font
            _graphWindow.Redraw()
        End If
        ColourGraphButtons()
        ArrangeGraphPage()
        ' Where the tabs' headers would run under the buttons (a small screen, large fonts), the
        ' buttons keep their row and the tabs go under it.
        If _tabs.TabCount > 0 Then
            Dim lastTab = _tabs.GetTabRect(_tabs.TabCount - 1)
            If _tabs.Left + lastTab.Right > _solver.Left - S(4) AndAlso _tabs.Top < _export.Bottom Then
                Dim top = _export.Bottom + S(2)
                _tabs.SetBounds(_tabs.Left, top, _tabs.Width, Math.Max(1, _tabs.Bottom - top))
            End If
            ' The strip right of the last header, in the panel's colour (under the header buttons).
            Dim last = _tabs.GetTabRect(_tabs.TabCount - 1)
            _tabStripFill.SetBounds(_tabs.Left + last.Right + S(2), _tabs.Top, Math.Max(1, _tabs.Width - last.Right - S(2)), last.Bottom)
            _tabStripFill.BringToFront()
            For Each b In {_solver, _export, _scenes, _restart}
                b.BringToFront()
            Next
        End If
    End Sub

    ''' <summary>The button of the graph on show is lit like a tool in use.</summary>
    Private Sub ColourGraphButtons()
        Dim theme = _presenter.Theme
        For i = 0 To _graphButtons.Count - 1
            _graphButtons(i).BackColor = ScenePainter.Rgb(If(i = CInt(_presenter.Graph), theme.MessageBack, theme.Button))
            _graphButtons(i).ForeColor = ScenePainter.Rgb(If(i = CInt(_presenter.Graph), theme.MessageText, theme.PanelText))
        Next
    End Sub

    ''' <summary>
    ''' The graph buttons in a row at the top of the page, then the gas controls, then the window
    ''' button at the right end; a second row when they do not fit in one. The graph under them.
    ''' </summary>
    Private Sub ArrangeGraphPage()
        If _presenter Is Nothing Then Return
        Dim w = _graphPage.ClientSize.Width, h = _graphPage.ClientSize.Height
        Dim rh = ButtonRowHeight()
        Dim x = S(4), y = S(3)
        Dim widthOf = Function(b As Button) Math.Max(S(60), Measure(b.Text, Font).Width + S(20))
        For Each b In _graphButtons
            b.SetBounds(x, y, widthOf(b), rh)
            x += b.Width + S(6)
        Next
        Dim gasWidth = _gasButtons.Sum(Function(g) widthOf(g.Button) + S(6)) + widthOf(_graphWindowButton) + S(12)
        If x + gasWidth > w Then
            x = S(4)
            y += rh + S(4)
        Else
            x += S(12)
        End If
        For Each g In _gasButtons
            g.Button.SetBounds(x, y, widthOf(g.Button), rh)
            x += g.Button.Width + S(6)
        Next
        ' The window button at the right end of the row.
        Dim ww = widthOf(_graphWindowButton)
        _graphWindowButton.SetBounds(Math.Max(x + S(6), w - ww - S(4)), y, ww, rh)
        Dim top = y + rh + S(4)
        _graphBox.SetBounds(0, top, Math.Max(1, w), Math.Max(1, h - top))
        _graphBox.Invalidate()
    End Sub

    ''' <summary>The graph tab's and Export's controls, by the names the --trace layout gives them.</summary>
    Private Function GraphControls() As IEnumerable(Of (Name As String, Control As Control))
        Dim named As New List(Of (Name As String, Control As Control)) From {("export", _export), ("solver", _solver)}
        ' The page's own controls only while it is on show: a hidden page has no place on the screen.
        If _tabs.SelectedTab IsNot _graphPage Then Return named
        For i = 0 To _graphButtons.Count - 1
            named.Add((GraphButtons(i).Name, _graphButtons(i)))
        Next
        named.Add(("graph-window", _graphWindowButton))
        For Each g In _gasButtons
            named.Add((g.Name, CType(g.Button, Control)))
        Next
        named.Add(("graph", _graphBox))
        Return named
    End Function

    ''' <summary>While the Graphs tab or the graph's window is on show, redraws the graph about ten times a second.</summary>
    Private Sub RefreshGraph(now As Double)
        Dim tab = _tabs.SelectedTab Is _graphPage
        If Not tab AndAlso _graphWindow Is Nothing Then Return
        If now - _graphDrawnAt < GraphSeconds Then Return
        _graphDrawnAt = now
        If tab Then _graphBox.Invalidate()
        _graphWindow?.Redraw()
    End Sub

    ''' <summary>Opens the graph in a window of its own (or brings it to the front), over most of the screen.</summary>
    Private Sub ShowGraphWindow()
        If _graphWindow Is Nothing Then
            Dim area = Screen.FromControl(Me).WorkingArea
            Dim bounds = New Drawing.Rectangle(area.X + area.Width \ 10, area.Y + area.Height \ 10, area.Width * 8 \ 10, area.Height * 8 \ 10)
            _graphWindow = New GraphWindow(_presenter, Font, _dpi.Scale, bounds)
            AddHandler _graphWindow.FormClosed,
                Sub(s, e)
                    _graphWindow.Dispose()
                    _graphWindow = Nothing
                    _trace?.Invoke("graph window closed")
                End Sub
            AddHandler _graphWindow.Shown,
                Sub(s, e)
                    Dim r = _graphWindow.GraphBounds
                    _trace?.Invoke("graph window shown " & r.X & " " & r.Y & " " & r.Width & " " & r.Height)
                End Sub
            _graphWindow.Show(Me)
        Else
            _graphWindow.Activate()
        End If
        _graphWindow.Redraw()
    End Sub

    Private Sub OnGraphPaint(sender As Object, e As PaintEventArgs)
        Dim start = Diagnostics.Stopwatch.GetTimestamp()
        Dim plot = _presenter.CurrentGraph()
        GraphPainter.Paint(e.Graphics, plot, _presenter.Theme, Font, _graphBox.ClientSize.Width, _graphBox.ClientSize.Height, _dpi.Scale)
        ' Drawn ten times a second, in some frame: the budget leaves room for it there (see FrameBudget).
        _presenter.NoteFrameWork((Diagnostics.Stopwatch.GetTimestamp() - start) / CDbl(Diagnostics.Stopwatch.Frequency))
        TraceGraph(plot)
    End Sub

    ''' <summary>
    ''' With --trace: what the graph shows when it changes: its kind, points per curve, and for the
    ''' histogram the total of its bars and each bar's count (GUI tests read these).
    ''' </summary>
    Private Sub TraceGraph(plot As GraphPlot)
        If _trace Is Nothing Then Return
        Dim cells As New List(Of String) From {_presenter.Graph.ToString()}
        cells.AddRange(plot.Lines.Select(Function(l) l.Name))
        If plot.Bars IsNot Nothing Then
            cells.Add("total " & plot.Bars.Total)
            cells.Add("bin " & plot.Bars.BinWidth.ToString("R", Globalization.CultureInfo.InvariantCulture))
            cells.Add("counts " & String.Join(" ", plot.Bars.Counts))
        End If
        cells.AddRange(plot.Notes)
        TraceShown("graph", cells.ToArray())
    End Sub

    ''' <summary>Drops the Export menu down under its button.</summary>
    Private Sub ShowExportMenu()
        For Each old In _exportMenu.Items.Cast(Of ToolStripItem)().ToList()
            old.Dispose()
        Next
        _exportMenu.Items.Clear()
        Dim theme = _presenter.Theme
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        _exportMenu.Font = Font
        _exportMenu.Renderer = If(theme.IsHighContrast, New ToolStripProfessionalRenderer(New LessonMenuColours()), New ToolStripProfessionalRenderer())
        _exportMenu.BackColor = back
        _exportMenu.ForeColor = fore
        For i = 0 To SimulationPresenter.ExportNames.Count - 1
            Dim kind = CType(i, ExportKind)
            Dim item As New ToolStripMenuItem(SimulationPresenter.ExportNames(i)) With {.BackColor = back, .ForeColor = fore}
            ' After the menu has closed, so the dialog is not opened from inside the menu's click.
            AddHandler item.Click, Sub(s, e) BeginInvoke(New Action(Sub() OnExport(kind)))
            _exportMenu.Items.Add(item)
        Next
        _exportMenu.Show(_export, New Point(0, _export.Height))
        If _trace IsNot Nothing Then
            For i = 0 To _exportMenu.Items.Count - 1
                Dim b = _exportMenu.Items(i).Bounds
                Dim p = _exportMenu.PointToScreen(b.Location)
                _trace("export item " & i & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & CType(i, ExportKind).ToString())
            Next
            _trace("export menu shown " & _exportMenu.Items.Count)
        End If
    End Sub

    ''' <summary>Asks where to save an export and writes it there (the presenter says what happened).</summary>
    Private Sub OnExport(kind As ExportKind)
        Dim png = kind = ExportKind.GraphPng OrElse kind = ExportKind.CanvasPng
        Dim title = "Export the " & SimulationPresenter.ExportNames(CInt(kind)).TrimEnd("…"c).ToLowerInvariant()
        Using d As New SaveFileDialog() With {
            .Title = title, .FileName = _presenter.ExportFileName(kind), .AddExtension = True, .OverwritePrompt = True,
            .DefaultExt = If(png, "png", "csv"),
            .Filter = If(png, "PNG pictures (*.png)|*.png", "CSV files (*.csv)|*.csv") & "|All files (*.*)|*.*"}
            _trace?.Invoke("export dialog " & kind.ToString())
            If d.ShowDialog(Me) <> DialogResult.OK Then Return
            Select Case kind
                Case ExportKind.GraphPng
                    ' A slide's size (16:9), whatever room the tab has on screen: the picture is for a worksheet or a slide.
                    Dim w = S(GraphPictureSize.Width), h = S(GraphPictureSize.Height)
                    SavePicture(kind, d.FileName, w, h, Sub(g) GraphPainter.Paint(g, _presenter.CurrentGraph(), _presenter.Theme, Font, w, h, _dpi.Scale))
                Case ExportKind.CanvasPng
                    Dim w = Math.Max(1, _canvas.ClientSize.Width), h = Math.Max(1, _canvas.ClientSize.Height)
                    SavePicture(kind, d.FileName, w, h, Sub(g) _painter.Paint(g, _presenter, w, h))
                Case Else
                    _presenter.ExportCsv(kind, d.FileName)
            End Select
        End Using
        _canvas.Invalidate()
    End Sub

    Private Sub SavePicture(kind As ExportKind, path As String, width As Integer, height As Integer, draw As Action(Of Graphics))
        Using bmp As New Bitmap(width, height)
            bmp.SetResolution(CSng(_dpi.Graphics), CSng(_dpi.Graphics))
            Using g = Graphics.FromImage(bmp)
                draw(g)
            End Using
            _presenter.ExportPicture(kind, path, Sub(s) bmp.Save(s, ImageFormat.Png), width, height)
        End Using
    End Sub

    ''' <summary>Every caption the solver's button can have: it is made wide enough for the longest, so it never moves.</summary>
    Private Shared Function SolverCaptions() As IEnumerable(Of String)
        Return SolverChoice.Names.Select(AddressOf SolverChoice.ButtonCaption)
    End Function

    ''' <summary>Drops the solver menu down under its button: each solver with a line on what it is for, the one in use ticked; kept on the screen.</summary>
    Private Sub ShowSolverMenu()
        For Each old In _solverMenu.Items.Cast(Of ToolStripItem)().ToList()
            old.Dispose()
        Next
        _solverMenu.Items.Clear()
        Dim theme = _presenter.Theme
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        _solverMenu.Font = Font
        _solverMenu.Renderer = If(theme.IsHighContrast, New ToolStripProfessionalRenderer(New LessonMenuColours()), New ToolStripProfessionalRenderer())
        _solverMenu.BackColor = back
        _solverMenu.ForeColor = fore
        _solverMenu.ShowItemToolTips = True
        For Each solverName In SolverChoice.Names
            Dim chosen = solverName
            Dim item As New ToolStripMenuItem(SolverChoice.MenuLine(chosen)) With {.BackColor = back, .ForeColor = fore, .ToolTipText = SolverChoice.Purpose(chosen),
                .Checked = (_presenter.SolverInUse = chosen)}
            AddHandler item.Click, Sub(s, e) Act(Sub() _presenter.ChooseSolver(chosen))
            _solverMenu.Items.Add(item)
        Next
        Dim area = Screen.FromControl(Me).WorkingArea
        Dim size = _solverMenu.GetPreferredSize(Drawing.Size.Empty)
        Dim at = _solver.PointToScreen(New Point(0, _solver.Height))
        at.X = Math.Max(area.Left, Math.Min(at.X, area.Right - size.Width))
        _solverMenu.Show(at)
        If _trace IsNot Nothing Then
            For i = 0 To _solverMenu.Items.Count - 1
                Dim b = _solverMenu.Items(i).Bounds
                Dim p = _solverMenu.PointToScreen(b.Location)
                _trace("solver item " & i & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & SolverChoice.Names(i))
            Next
            TraceMenuBounds("solver menu", _solverMenu)
            _trace("solver menu shown " & _solverMenu.Items.Count)
        End If
    End Sub

    Private Sub DisposeGraphControls()
        _solverMenu.Dispose()
        _exportMenu.Dispose()
    End Sub
End Class
