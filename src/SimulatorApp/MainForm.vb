Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The main window: a passive view over <see cref="SimulationPresenter"/>. Its handlers forward the
''' teacher's actions to the presenter, which also decides what every label, slider and table shows
''' and what happens when something fails; this class only lays the controls out and draws.
''' </summary>
Partial Friend NotInheritable Class MainForm
    Inherits Form
    Implements ISimulationView

    Public Const Title As String = "Collision Simulator"
    ''' <summary>The window's size at 96 dpi when the screen has room for it, px.</summary>
    Private Shared ReadOnly PreferredSize96 As New Size(1280, 800)

    Private Shared ReadOnly BlankRow As String() = New String(9) {}
    Private Shared ReadOnly BlankLinkRow As String() = New String(LinkTable.Headers.Count - 1) {}

    Private ReadOnly _presenter As SimulationPresenter
    Private ReadOnly _painter As ScenePainter
    Private ReadOnly _trace As Action(Of String)
    Private ReadOnly _dpi As ScreenDpi
    Private ReadOnly _timer As New Timer()
    Private ReadOnly _clock As Diagnostics.Stopwatch = Diagnostics.Stopwatch.StartNew()
    Private _lastTick As Double
    Private _updating As Boolean
    Private _logVersion As Long = -1
    Private _logWidthsAt As Double = -1

    Private ReadOnly _canvas As New PictureBox()
    Private ReadOnly _totals As New Label()
    Private ReadOnly _tabs As New TabControl()
    ''' <summary>Covers the strip beside the tabs' headers, which Mono paints light grey whatever the theme.</summary>
    Private ReadOnly _tabStripFill As New Panel()
    Private ReadOnly _tables As New List(Of BufferedListView)
    Private ReadOnly _logList As New BufferedListView()
    ''' <summary>The side panel as it shows on screen: a window onto <see cref="_side"/>, which scrolls with its own bar and the wheel.</summary>
    Private ReadOnly _sideView As New ScrollingPanel()
    ''' <summary>The side panel's controls live here, at fixed places: only a scroll the teacher asks for moves them.</summary>
    Private ReadOnly _side As Panel = _sideView.Content
    ''' <summary>The message area: a fixed height on top of the panel, scrolling within itself when a message is longer.</summary>
    Private ReadOnly _message As New MessageArea()
    Private ReadOnly _wheel As New WheelRouter()
    Private ReadOnly _pause As New Button()
    Private ReadOnly _reset As New Button()
    Private ReadOnly _deleteMode As New Button()
    Private ReadOnly _speedLabel As New Label()
    Private ReadOnly _speed As New ScaledSlider()
    Private ReadOnly _gravityLabel As New Label()
    Private ReadOnly _gravity As New ScaledSlider()
    Private ReadOnly _gravityMarks As New List(Of Button)
    Private ReadOnly _restitutionLabel As New Label()
    Private ReadOnly _restitution As New ScaledSlider()
    Private ReadOnly _frictionLabel As New Label()
    Private ReadOnly _friction As New TextBox()
    Private ReadOnly _staticFrictionLabel As New Label()
    Private ReadOnly _staticFriction As New TextBox()
    Private ReadOnly _setFriction As New Button()
    Private ReadOnly _radiusLabel As New Label()
    Private ReadOnly _radius As New TextBox()
    Private ReadOnly _massLabel As New Label()
    Private ReadOnly _mass As New TextBox()
    Private ReadOnly _fixed As New ScaledCheckBox()
    Private ReadOnly _addCircle As New Button()
    Private ReadOnly _widthLabel As New Label()
    Private ReadOnly _rectWidth As New TextBox()
    Private ReadOnly _heightLabel As New Label()
    Private ReadOnly _rectHeight As New TextBox()
    Private ReadOnly _addRectangle As New Button()
    Private ReadOnly _rectFixed As New ScaledCheckBox()
    Private ReadOnly _sidesLabel As New Label()
    Private ReadOnly _sides As New TextBox()
    Private ReadOnly _angleLabel As New Label()
    Private ReadOnly _angle As New TextBox()
    Private ReadOnly _addPolygon As New Button()
    Private ReadOnly _addCorners As New Button()
    Private ReadOnly _stiffnessLabel As New Label()
    Private ReadOnly _stiffness As New TextBox()
    Private ReadOnly _addSpring As New Button()
    Private ReadOnly _addRod As New Button()
    Private ReadOnly _addString As New Button()
    Private ReadOnly _addRamp As New Button()
    Private ReadOnly _linkList As New BufferedListView()
    Private ReadOnly _boxWidthLabel As New Label()
    Private ReadOnly _boxWidth As New TextBox()
    Private ReadOnly _boxHeightLabel As New Label()
    Private ReadOnly _boxHeight As New TextBox()
    Private ReadOnly _resize As New Button()
    Private ReadOnly _largeFonts As New ScaledCheckBox()
    Private ReadOnly _highContrast As New ScaledCheckBox()
    Private ReadOnly _arrows As New ScaledCheckBox()
    Private ReadOnly _grid As New ScaledCheckBox()
    Private ReadOnly _tutorial As New Button()
    Private ReadOnly _maths As New Button()
    Private ReadOnly _open As New Button()
    Private ReadOnly _save As New Button()
    Private ReadOnly _inputs As New Dictionary(Of InputField, TextBox)
    ''' <summary>The header row's buttons, right of the tabs: the solver, Export, Scenes, Restart.</summary>
    Private ReadOnly _solver As New Button()
    Private ReadOnly _export As New Button()
    Private ReadOnly _scenes As New Button()
    Private ReadOnly _restart As New Button()
    ''' <summary>The Measure button of the header row: the tape, the pass timer and the stopwatch.</summary>
    Private ReadOnly _measure As New Button()

    ''' <summary>What the window's parts share (the presenter, the trace, the screen's scale, text measures, tips).</summary>
    Private ReadOnly _kit As WindowKit
    ''' <summary>The side panel's rows.</summary>
    Private ReadOnly _rows As PanelRows
    ''' <summary>The player row: steps and the timeline.</summary>
    Private _time As TimeControls
    ''' <summary>The momentum views' check boxes.</summary>
    Private _momentumBoxes As MomentumBoxes
    ''' <summary>The edit box of the body tables.</summary>
    Private _cells As TableCells
    ''' <summary>The Graphs tab.</summary>
    Private _graphs As GraphsPage
    Private _forcesPage As ForcesPage
    Private _lessonMenu As LessonMenu
    Private _solverMenu As SolverMenu
    Private _exportMenu As ExportMenu
    Private _measureMenu As MeasureMenu

    ''' <param name="trace">receives one line per action when the app runs with --trace; Nothing otherwise</param>
    ''' <param name="store">scene files; Nothing disables Open and Save</param>
    ''' <param name="world">the opening scene; Nothing for the demo</param>
    ''' <param name="sceneFolder">where Open and Save start</param>
    Public Sub New(trace As Action(Of String), store As ISceneStore, Optional world As World = Nothing, Optional sceneFolder As String = Nothing)
        _trace = trace
        _dpi = ScreenDpi.Detect()
        _kit = New WindowKit(Me, _dpi, trace, AddressOf Act)
        _rows = New PanelRows(_kit)
        _painter = New ScenePainter(_dpi.FontScale)
        SuspendLayout()
        ' Sizes are computed here from the screen's DPI (see S), so the runtime must not scale them again.
        AutoScaleMode = AutoScaleMode.None
        Text = Title
        KeyPreview = True
        FitToScreen()
        BuildControls()
        ResumeLayout(False)

        _presenter = New SimulationPresenter(Me, store, world) With {.Trace = trace, .ScreenScale = _dpi.Scale, .SceneFolder = sceneFolder, .LessonFolder = sceneFolder}
        _kit.Presenter = _presenter
        _trace?.Invoke("dpi " & Units.Num(_dpi.Screen, 0) & " (" & _dpi.Source & "), gdi+ " & Units.Num(_dpi.Graphics, 0) & ", scale " & Units.Num(_dpi.Scale, 2))
        ShowTheme()
        ShowSettings()
        ShowInputs()
        ShowState()
        ShowMessage("")

        _timer.Interval = 16
        AddHandler _timer.Tick, AddressOf OnTimerTick
    End Sub

    ''' <summary>The presenter (the frame benchmark paints through it the same way).</summary>
    Friend ReadOnly Property Presenter As SimulationPresenter
        Get
            Return _presenter
        End Get
    End Property

    ''' <summary>Opens as large as it was designed (1280 × 800 at 96 dpi, more on a denser screen), but never larger than the screen the cursor is on.</summary>
    Private Sub FitToScreen()
        StartPosition = FormStartPosition.Manual
        Dim area = Screen.FromPoint(Control.MousePosition).WorkingArea
        Dim wanted = New Size(S(PreferredSize96.Width), S(PreferredSize96.Height))
        Dim chrome = Size - ClientSize ' title bar and borders, where a window manager draws them
        Dim w = Math.Min(wanted.Width + chrome.Width, area.Width)
        Dim h = Math.Min(wanted.Height + chrome.Height, area.Height)
        Bounds = New Drawing.Rectangle(area.X, area.Y, w, h)
        MinimumSize = New Size(Math.Min(S(800), area.Width), Math.Min(S(560), area.Height))
    End Sub

    Private Sub BuildControls()
        AddHandler _canvas.Paint, AddressOf OnCanvasPaint
        AddHandler _canvas.MouseDown, AddressOf OnCanvasMouseDown
        AddHandler _canvas.MouseMove, AddressOf OnCanvasMouseMove
        AddHandler _canvas.MouseUp, AddressOf OnCanvasMouseUp
        AddHandler _canvas.Resize, Sub(s, e) _presenter?.CanvasResized(_canvas.ClientSize.Width, _canvas.ClientSize.Height)
        Controls.Add(_canvas)

        _totals.TextAlign = ContentAlignment.MiddleLeft
        _totals.UseMnemonic = False
        Controls.Add(_totals)

        For Each t In SimulationPresenter.Tables
            Dim list As New BufferedListView()
            SetUpTable(list, t.Headers, AddressOf OnRetrieveRow)
            ' The headers are short (every column shows at once); the tip says what they hold.
            _kit.Tips.SetToolTip(list, t.Tip)
            AddTab(t.Title, list)
            _tables.Add(list)
        Next
        SetUpTable(_linkList, LinkTable.Headers, AddressOf OnRetrieveLink)
        AddTab(LinkTable.Title, _linkList)
        SetUpTable(_logList, CollisionLogEntry.Headers, AddressOf OnRetrieveLog)
        AddTab(Captions.CollisionLog, _logList)
        _graphs = New GraphsPage(_kit, AddressOf TraceShown)
        _tabs.TabPages.Add(_graphs.Page)
        _forcesPage = New ForcesPage(_kit, AddressOf TraceShown)
        _tabs.TabPages.Add(_forcesPage.Page)
        ' The header row's buttons, right of the tabs, where there is room at every screen size: the
        ' side panel has no row to spare on a 1024 × 768 projector.
        AddHeaderButton(_solver, "Solver ▾", Sub() _solverMenu.Show())
        AddHeaderButton(_export, SimulationPresenter.ExportCaption, Sub() _exportMenu.Show())
        AddHeaderButton(_scenes, SimulationPresenter.ScenesCaption, Sub() _lessonMenu.Show())
        AddHeaderButton(_restart, SimulationPresenter.RestartCaption, Sub() _presenter.Restart())
        _solverMenu = New SolverMenu(_kit, _solver)
        _exportMenu = New ExportMenu(_kit, _export, _canvas, _painter)
        _lessonMenu = New LessonMenu(_kit, _scenes)
        AddHeaderButton(_measure, MeasureMenu.Caption, Sub() _measureMenu.Show())
        _measureMenu = New MeasureMenu(_kit, _measure)
        _kit.Tips.SetToolTip(_measure, "The tape measure, a stopwatch on simulated time, and the timing of a body's passes through a line")
        _kit.Tips.SetToolTip(_solver, "How the scene is moved on in time: choose another, then Restart, to compare")
        _kit.Tips.SetToolTip(_export, "Save the tables, the collision log or the graph as CSV, or the graph or the canvas as a picture")
        _kit.Tips.SetToolTip(_scenes, "Ready-made lesson scenes (" & SimulationPresenter.ScenesKey & ")")
        _kit.Tips.SetToolTip(_restart, "Back to the scene as it was opened or last built (" & SimulationPresenter.RestartKey & ")")
        ' Mono leaves a details list's header unpainted when its tab comes back: repaint the list then.
        AddHandler _tabs.SelectedIndexChanged, AddressOf OnTabChanged
        ' The tabs' headers are drawn here: in the theme's colours (Mono leaves them light grey in high
        ' contrast), and as tall as the text at any DPI (Mono keeps them 96-dpi high).
        _tabs.DrawMode = TabDrawMode.OwnerDrawFixed
        AddHandler _tabs.DrawItem, AddressOf OnDrawTab
        Controls.Add(_tabStripFill)
        Controls.Add(_tabs)

        ' With --trace, where the controls are after the panel scrolls (GUI tests click them there).
        AddHandler _sideView.Scrolled, Sub(s, a) If IsHandleCreated Then TraceLayout()
        ' The wheel anywhere over the panel scrolls it (a long message scrolls within its own box).
        ' Each turn is acknowledged in the trace after its effect (the new layout, when the panel moved),
        ' so a GUI test waits for the app to have handled its own turn, not for any layout line.
        _wheel.Add(_message,
            Sub(delta, p)
                ScrollMessage(delta)
                _trace?.Invoke("wheel side " & delta & " scrolled " & _sideView.Offset)
            End Sub)
        _wheel.Add(_sideView,
            Sub(delta, p)
                _sideView.ScrollBy(-Math.Sign(delta) * 3 * LineHeight(Font))
                _trace?.Invoke("wheel side " & delta & " scrolled " & _sideView.Offset)
            End Sub)
        ' The wheel over the canvas zooms about the cursor.
        _wheel.Add(_canvas, Sub(delta, p) Act(Sub() _presenter.ZoomAt(delta / 120.0, p.X, p.Y)))
        Application.AddMessageFilter(_wheel)
        Controls.Add(_sideView)
        _message.ScreenScale = _dpi.Scale
        _message.SetMeasure(Function(text, font, width) Measure(text, font, width))
        _side.Controls.Add(_message)

        AddButton(_pause, "Pause", Sub() _presenter.TogglePause())
        AddButton(_reset, Captions.Reset, Sub() _presenter.Reset())
        AddButton(_deleteMode, "Delete mode", Sub() _presenter.ToggleDeleteMode())
        _kit.Tips.SetToolTip(_pause, "Pause or resume (" & SimulationPresenter.PauseKey & ")")
        _kit.Tips.SetToolTip(_reset, "Remove every body (" & SimulationPresenter.ResetKey & ")")

        AddLabel(_speedLabel, "")
        SetUpSlider(_speed, SpeedSteps.Values.Count - 1, 1, Sub() _presenter.SetSpeedIndex(_speed.Value))
        AddLabel(_gravityLabel, "")
        Dim g = SimulationPresenter.GravitySlider
        SetUpSlider(_gravity, g.Steps, g.PositionOf(10) - g.PositionOf(0), Sub() _presenter.GravitySliderMoved(_gravity.Value))
        _gravity.SmallChange = g.PositionOf(0.1) - g.PositionOf(0)
        _gravity.LargeChange = g.PositionOf(1) - g.PositionOf(0)
        For Each mark In GravityMark.All
            Dim b As New Button()
            Dim value = mark.Value
            AddButton(b, SimulationPresenter.GravityMarkText(mark), Sub() _presenter.SetGravity(value))
            _gravityMarks.Add(b)
        Next
        AddLabel(_restitutionLabel, "")
        Dim rs = SimulationPresenter.RestitutionSlider
        SetUpSlider(_restitution, rs.Steps, rs.PositionOf(0.1), Sub() _presenter.RestitutionSliderMoved(_restitution.Value))
        _restitution.LargeChange = rs.PositionOf(0.1)
        AddField(_frictionLabel, "Friction μk", _friction, InputField.FrictionKinetic)
        AddField(_staticFrictionLabel, "μs", _staticFriction, InputField.FrictionStatic)
        AddButton(_setFriction, Captions.SetFriction, Sub() _presenter.SetFriction())
        ' Where μ is set, the teacher learns that balls take no friction.
        Dim frictionTip = "μk: sliding friction; μs: static friction (empty: the same as μk), of walls, ramps, fixed bodies, boxes and polygons. " & SimulationPresenter.FrictionBallsNote
        For Each c In New Control() {_frictionLabel, _friction, _staticFrictionLabel, _staticFriction, _setFriction}
            _kit.Tips.SetToolTip(c, frictionTip)
        Next

        AddField(_radiusLabel, "Radius (m)", _radius, InputField.Radius)
        AddField(_massLabel, "Mass (kg)", _mass, InputField.Mass)
        _fixed.Text = Captions.Fixed
        _fixed.ScreenScale = _dpi.Scale
        AddHandler _fixed.CheckedChanged, Sub(s, a) If Not _updating Then _presenter.FixedChanged(_fixed.Checked)
        _side.Controls.Add(_fixed)
        AddButton(_addCircle, Captions.AddCircle, Sub() _presenter.BeginAddCircle())

        AddField(_widthLabel, "Rectangle w (m)", _rectWidth, InputField.RectangleWidth)
        AddField(_heightLabel, "h (m)", _rectHeight, InputField.RectangleHeight)
        _rectFixed.Text = Captions.Fixed
        _rectFixed.ScreenScale = _dpi.Scale
        AddHandler _rectFixed.CheckedChanged, Sub(s, a) If Not _updating Then _presenter.RectangleFixedChanged(_rectFixed.Checked)
        _side.Controls.Add(_rectFixed)
        AddButton(_addRectangle, Captions.AddRectangle, Sub() _presenter.BeginAddRectangle())

        AddField(_sidesLabel, "Sides n", _sides, InputField.Sides)
        AddField(_angleLabel, "Angle (°)", _angle, InputField.PolygonAngle)
        AddButton(_addPolygon, Captions.AddPolygon, Sub() _presenter.BeginAddPolygon())
        AddButton(_addCorners, Captions.AddByCorners, Sub() _presenter.BeginAddCorners())

        AddField(_stiffnessLabel, "k (N/m)", _stiffness, InputField.Stiffness)
        AddButton(_addSpring, Captions.AddSpring, Sub() _presenter.BeginAddLink(LinkKind.Spring))
        AddButton(_addRod, Captions.AddRod, Sub() _presenter.BeginAddLink(LinkKind.Rod))
        AddButton(_addString, Captions.AddString, Sub() _presenter.BeginAddLink(LinkKind.String))
        AddButton(_addRamp, Captions.AddRamp, Sub() _presenter.BeginAddRamp())
        SetUpLiquidControls()

        AddField(_boxWidthLabel, "Container w (m)", _boxWidth, InputField.ContainerWidth)
        AddField(_boxHeightLabel, "h (m)", _boxHeight, InputField.ContainerHeight)
        AddButton(_resize, Captions.ResizeContainer, Sub() _presenter.ResizeContainer())

        AddCheck(_largeFonts, Captions.LargeFonts, Sub() _presenter.SetLargeFonts(_largeFonts.Checked))
        AddCheck(_highContrast, Captions.HighContrast, Sub() _presenter.SetHighContrast(_highContrast.Checked))
        AddCheck(_arrows, Captions.Arrows, Sub() _presenter.SetShowArrows(_arrows.Checked))
        AddCheck(_grid, Captions.Grid, Sub() _presenter.SetShowGrid(_grid.Checked))
        _kit.Tips.SetToolTip(_grid, "Lines every metre and every 10 cm under the bodies, to read positions and lengths off the canvas")
        AddButton(_tutorial, Captions.Tutorial, Sub() ShowHelp(Captions.Tutorial, HelpTexts.Tutorial))
        AddButton(_maths, Captions.MathsUsed, Sub() ShowHelp(Captions.MathsUsed, HelpTexts.Maths))
        AddButton(_open, Captions.OpenScene, AddressOf OnOpen)
        AddButton(_save, Captions.SaveScene, AddressOf OnSave)
        _momentumBoxes = New MomentumBoxes(_kit, _side)
        _cells = New TableCells(_kit, Me, _tables)
        _time = New TimeControls(_kit, _side)
        ' Every control of the side panel says when it takes the focus, so a test can follow Tab; and
        ' Tab to a control below the panel's visible part scrolls it into view.
        For Each c As Control In _side.Controls
            Dim control = c
            AddHandler control.GotFocus,
                Sub(s, e)
                    _sideView.EnsureVisible(control)
                    If _trace Is Nothing Then Return
                    Dim p = control.PointToScreen(Point.Empty)
                    Dim name = NamedControls().FirstOrDefault(Function(n) n.Control Is control).Name
                    _trace("focus " & p.X & " " & p.Y & " " & control.GetType().Name & " " & If(name, "-"))
                End Sub
        Next
    End Sub

    ''' <summary>A button of the header row, right of the tabs (on the window, not the side panel).</summary>
    Private Sub AddHeaderButton(button As Button, text As String, action As Action)
        button.Text = text
        button.UseMnemonic = False
        AddHandler button.Click, Sub(s, e) Act(action)
        Controls.Add(button)
        button.BringToFront()
    End Sub

    Private Sub AddTab(title As String, list As BufferedListView)
        Dim page As New TabPage(title)
        list.Dock = DockStyle.Fill
        page.Controls.Add(list)
        _tabs.TabPages.Add(page)
    End Sub

    Private Shared Sub SetUpTable(list As BufferedListView, headers As IReadOnlyList(Of String), retrieve As RetrieveVirtualItemEventHandler)
        For Each h In headers
            list.Columns.Add(h, 100)
        Next
        AddHandler list.RetrieveVirtualItem, retrieve
    End Sub

    Private Sub AddLabel(label As Label, text As String)
        label.Text = text
        label.AutoSize = False
        label.UseMnemonic = False
        label.TextAlign = ContentAlignment.MiddleLeft
        _side.Controls.Add(label)
    End Sub

    Private Sub AddField(label As Label, text As String, box As TextBox, field As InputField)
        AddLabel(label, text)
        _inputs(field) = box
        ' One line as tall as the layout makes it (a line of text and a margin), the text in its middle:
        ' Mono would otherwise size it from the DPI it reports, not the one it draws at.
        WindowKit.KeepToOneLine(box, _trace, field.ToString())
        ' Every edit goes to the presenter at once, so what was typed is what it knows.
        AddHandler box.TextChanged,
            Sub(s, a)
                ' A pasted line break is taken out first (the box then changes again, without it).
                If box.Text.Contains(vbCr) OrElse box.Text.Contains(vbLf) OrElse _updating Then Return
                _presenter.InputChanged(field, box.Text)
                TraceInputs()
            End Sub
        _side.Controls.Add(box)
    End Sub

    Private Sub AddButton(button As Button, text As String, action As Action)
        button.Text = text
        button.UseMnemonic = False
        AddHandler button.Click, Sub(s, e) Act(action)
        _side.Controls.Add(button)
    End Sub

    Private Sub AddCheck(box As ScaledCheckBox, text As String, action As Action)
        box.Text = text
        box.ScreenScale = _dpi.Scale
        AddHandler box.CheckedChanged, Sub(s, e) If Not _updating Then Act(action)
        _side.Controls.Add(box)
    End Sub

    Private Sub SetUpSlider(slider As ScaledSlider, max As Integer, tick As Integer, action As Action)
        slider.ScreenScale = _dpi.Scale
        slider.Minimum = 0
        slider.Maximum = max
        slider.TickFrequency = Math.Max(1, tick)
        AddHandler slider.ValueChanged, Sub(s, e) If Not _updating Then Act(action)
        _side.Controls.Add(slider)
    End Sub

    ''' <summary>Runs a teacher's action and redraws. The presenter turns failures into messages.</summary>
    Private Sub Act(action As Action)
        action()
        _canvas.Invalidate()
    End Sub

    Private Sub ShowHelp(title As String, topics As IReadOnlyList(Of HelpTopic))
        Dim f As New HelpForm(title & " — " & MainForm.Title, topics, Font, _presenter.Theme, _dpi.Scale, _trace)
        AddHandler f.FormClosed, Sub(s, e) f.Dispose()
        f.Show(Me)
        _trace?.Invoke("help " & title)
    End Sub

    Private Sub OnOpen()
        If Not _presenter.CanOpenAndSave Then
            _presenter.OpenScene(Nothing)
            Return
        End If
        Using d As New OpenFileDialog() With {.Filter = "Scene files (*.json)|*.json|All files (*.*)|*.*", .Title = "Open a scene", .InitialDirectory = If(_presenter.SceneFolder, "")}
            If d.ShowDialog(Me) = DialogResult.OK Then _presenter.OpenScene(d.FileName)
        End Using
    End Sub

    Private Sub OnSave()
        If Not _presenter.CanOpenAndSave Then
            _presenter.SaveScene(Nothing)
            Return
        End If
        Using d As New SaveFileDialog() With {.Filter = "Scene files (*.json)|*.json", .Title = "Save the scene", .DefaultExt = "json", .AddExtension = True, .InitialDirectory = If(_presenter.SceneFolder, "")}
            If d.ShowDialog(Me) = DialogResult.OK Then _presenter.SaveScene(d.FileName)
        End Using
    End Sub

    Protected Overrides Sub OnShown(e As EventArgs)
        MyBase.OnShown(e)
        ArrangeControls()
        _lastTick = _clock.Elapsed.TotalSeconds
        _timer.Start()
        TraceLayout()
    End Sub

    ''' <summary>The keys of the window, wherever the focus is (a text box keeps its own Ctrl+Z and Ctrl+Y, and the time keys).</summary>
    Protected Overrides Function ProcessCmdKey(ByRef msg As Message, keyData As Keys) As Boolean
        Select Case keyData
            Case Keys.Control Or Keys.P
                _trace?.Invoke("key pause")
                Act(Sub() _presenter.TogglePause())
                Return True
            Case Keys.Control Or Keys.R
                _trace?.Invoke("key restart")
                Act(Sub() _presenter.Restart())
                Return True
            Case Keys.Control Or Keys.Shift Or Keys.R
                _trace?.Invoke("key reset")
                Act(Sub() _presenter.Reset())
                Return True
            Case Keys.Control Or Keys.L
                _trace?.Invoke("key scenes")
                _lessonMenu.Show()
                Return True
        End Select
        If keyData = (Keys.Control Or Keys.D0) OrElse keyData = (Keys.Control Or Keys.NumPad0) Then
            _trace?.Invoke("key whole view")
            Act(Sub() _presenter.ResetView())
            Return True
        End If
        ' Undo and redo, except in a text box, which undoes its own typing.
        If Not TypeOf ActiveControl Is TextBox Then
            Select Case keyData
                Case Keys.Control Or Keys.Z
                    _trace?.Invoke("key undo")
                    Act(Sub() _presenter.Undo())
                    Return True
                Case Keys.Control Or Keys.Y, Keys.Control Or Keys.Shift Or Keys.Z
                    _trace?.Invoke("key redo")
                    Act(Sub() _presenter.Redo())
                    Return True
            End Select
        End If
        If _time.ProcessKey(keyData, ActiveControl) Then Return True
        If ProcessCornerKey(keyData) Then Return True
        Return MyBase.ProcessCmdKey(msg, keyData)
    End Function

    ''' <summary>
    ''' Enter finishes a polygon drawn by its corners, wherever the focus is (a focused button would
    ''' otherwise take Enter as a click); an open table edit box keeps its Enter.
    ''' </summary>
    Private Function ProcessCornerKey(keyData As Keys) As Boolean
        If keyData <> Keys.Enter OrElse _presenter Is Nothing OrElse _presenter.Mode <> ClickMode.Corners OrElse _cells.IsOpen Then Return False
        _trace?.Invoke("key finish corners")
        Act(Sub() _presenter.FinishCorners())
        Return True
    End Function

    Protected Overrides Sub OnKeyDown(e As KeyEventArgs)
        MyBase.OnKeyDown(e)
        If e IsNot Nothing AndAlso e.KeyCode = Keys.Escape Then
            Act(Sub() _presenter.CancelPlacement())
            e.Handled = True
        End If
    End Sub

    Protected Overrides Sub OnResize(e As EventArgs)
        MyBase.OnResize(e)
        If IsHandleCreated AndAlso _presenter IsNot Nothing Then ArrangeControls()
    End Sub

    Private Sub OnTimerTick(sender As Object, e As EventArgs)
        Dim now = _clock.Elapsed.TotalSeconds
        Dim dt = now - _lastTick
        _lastTick = now
        _presenter.Tick(dt)
        _canvas.Invalidate()
        Dim refreshStart = _clock.Elapsed.TotalSeconds
        RefreshLog(now)
        _graphs.Refresh(now, _tabs.SelectedTab Is _graphs.Page)
        _forcesPage.Refresh(now, _tabs.SelectedTab Is _forcesPage.Page)
        Dim refreshEnd = _clock.Elapsed.TotalSeconds
        ' The log and the graph are part of the frame too: the next frames' budget leaves room for them.
        _presenter.NoteFrameWork(refreshEnd - refreshStart)
        FrameStats?.Record(dt, refreshEnd - now)
    End Sub

    ''' <summary>Frame timing for --stats; Nothing when not asked for.</summary>
    Friend Property FrameStats As FrameStats

    Private Sub RefreshLog(now As Double)
        If _tabs.SelectedIndex <> _tables.Count + 1 OrElse _logVersion = _presenter.Log.Version Then Return
        _logVersion = _presenter.Log.Version
        If _logList.VirtualListSize <> _presenter.Log.Count Then
            _logList.VirtualListSize = _presenter.Log.Count
            _trace?.Invoke("log rows " & _presenter.Log.Count)
        End If
        ' Columns grow to fit what they hold (measured at most twice a second), so nothing is cut off.
        If now - _logWidthsAt > 0.5 Then
            _logWidthsAt = now
            FitLogColumns()
        End If
        _logList.Invalidate()
    End Sub

    ''' <summary>Draws one tab's header: the chosen tab in the canvas's colours, the others as buttons, the title in the panel's text colour.</summary>
    Private Sub OnDrawTab(sender As Object, e As DrawItemEventArgs)
        If _presenter Is Nothing OrElse e.Index < 0 OrElse e.Index >= _tabs.TabCount Then Return
        Dim theme = _presenter.Theme
        Dim chosen = e.Index = _tabs.SelectedIndex
        Dim r = e.Bounds
        Using back As New SolidBrush(ScenePainter.Rgb(If(chosen, theme.Field, theme.Button))), edge As New Pen(ScenePainter.Rgb(theme.PanelText), CSng(Math.Max(1, S(1))))
            e.Graphics.FillRectangle(back, r)
            If theme.IsHighContrast OrElse chosen Then e.Graphics.DrawRectangle(edge, r.X, r.Y, r.Width - 1, r.Height - 1)
        End Using
        Using ink As New SolidBrush(ScenePainter.Rgb(theme.PanelText)), format As New StringFormat() With {.Alignment = StringAlignment.Center, .LineAlignment = StringAlignment.Center, .FormatFlags = StringFormatFlags.NoWrap}
            e.Graphics.DrawString(_tabs.TabPages(e.Index).Text, Font, ink, New RectangleF(r.X, r.Y, r.Width, r.Height), format)
        End Using
        ' The chosen tab is marked by a bar along its top, in the cue's colour (not a colour the canvas uses for physics).
        If chosen Then
            Using bar As New SolidBrush(ScenePainter.Rgb(theme.Cue))
                e.Graphics.FillRectangle(bar, r.X + 1, r.Y + 1, r.Width - 2, Math.Max(2, S(3)))
            End Using
        End If
    End Sub

    Private Sub OnTabChanged(sender As Object, e As EventArgs)
        Dim page = _tabs.SelectedTab
        If page Is Nothing OrElse page.Controls.Count = 0 Then Return
        Dim list = TryCast(page.Controls(0), BufferedListView)
        If list Is Nothing Then ' the Graphs and Forces tabs
            ' Mono sizes a text box again when its page first shows (from the font height it reports): the Forces page is laid out again then.
            If page Is _forcesPage.Page Then
                _forcesPage.Arrange()
                _presenter.ExplainForces()
            End If
            _trace?.Invoke("tab " & page.Text)
            TraceLayout()
            Return
        End If
        ' Mono lays a details list's header out only while the list is on screen: a list whose rows or
        ' columns changed behind another tab comes back with a blank header row. Its rows are set now
        ' (see ShowState), and a column is nudged so the header is laid out and painted again.
        Dim t = _tables.IndexOf(list)
        If t >= 0 Then list.VirtualListSize = _presenter.Snapshot.RowCount(t)
        If list Is _linkList Then list.VirtualListSize = _presenter.Snapshot.LinkCount
        ' Values that grew while the table was behind another tab get their room now.
        _columnsGrownAt = -1
        If t >= 0 OrElse list Is _linkList Then GrowColumns(list)
        If list.Columns.Count > 0 Then
            Dim first = list.Columns(0)
            first.Width += 1
            first.Width -= 1
        End If
        list.Refresh()
        _logVersion = -1
        If t >= 0 OrElse list Is _linkList Then TraceColumnEdge(list)
        _trace?.Invoke("tab " & page.Text)
    End Sub

    Private Sub OnRetrieveRow(sender As Object, e As RetrieveVirtualItemEventArgs)
        Dim t = _tables.IndexOf(DirectCast(sender, BufferedListView))
        Dim snap = _presenter.Snapshot
        If t < 0 OrElse e.ItemIndex >= snap.RowCount(t) Then
            e.Item = New ListViewItem(BlankRow)
            Return
        End If
        Dim cells = snap.Cells(t, e.ItemIndex)
        e.Item = Row(cells)
        TraceShown("row " & SimulationPresenter.Tables(t).Title & " " & e.ItemIndex, cells)
    End Sub

    Private ReadOnly _traced As New Dictionary(Of String, String)(StringComparer.Ordinal)

    ''' <summary>With --trace: what a list has just been given to draw, when it differs from last time (GUI tests read the tables through this).</summary>
    Private Sub TraceShown(what As String, cells As String())
        If _trace Is Nothing Then Return
        Dim text = String.Join(" | ", cells)
        Dim last As String = Nothing
        If _traced.TryGetValue(what, last) AndAlso last = text Then Return
        _traced(what) = text
        _trace(what & ": " & text)
    End Sub

    Private Sub OnRetrieveLink(sender As Object, e As RetrieveVirtualItemEventArgs)
        Dim snap = _presenter.Snapshot
        If e.ItemIndex >= snap.LinkCount Then
            e.Item = New ListViewItem(BlankLinkRow)
            Return
        End If
        Dim cells = snap.LinkCells(e.ItemIndex)
        e.Item = New ListViewItem(cells)
        TraceShown("row " & LinkTable.Title & " " & e.ItemIndex, cells)
    End Sub

    Private Sub OnRetrieveLog(sender As Object, e As RetrieveVirtualItemEventArgs)
        Dim log = _presenter.Log
        Dim cells = If(e.ItemIndex < log.Count, log(e.ItemIndex).Cells(), BlankRow)
        e.Item = New ListViewItem(cells)
        If e.ItemIndex < log.Count Then TraceShown("log " & e.ItemIndex, cells)
    End Sub

    ''' <summary>A table row whose colour cell is filled with the body's colour.</summary>
    Private Function Row(cells As String()) As ListViewItem
        Dim item As New ListViewItem(cells) With {.UseItemStyleForSubItems = False}
        Dim theme = _presenter.Theme
        For Each s As ListViewItem.ListViewSubItem In item.SubItems
            s.BackColor = ScenePainter.Rgb(theme.Panel)
            s.ForeColor = ScenePainter.Rgb(theme.PanelText)
        Next
        ' The colour the canvas draws the body in: its own, or the theme's fixed grey.
        Dim colour = If(cells(1) = BodyTable.FixedColourCell, theme.Fixed, BodyColours.Parse(cells(1), -1))
        If colour >= 0 Then
            item.SubItems(1).BackColor = ScenePainter.Rgb(colour)
            ' Dark text on a light colour, white on a dark one: readable on every swatch.
            item.SubItems(1).ForeColor = If(BodyColours.Luminance(colour) > 0.45, Color.Black, Color.White)
        End If
        Return item
    End Function

    ''' <summary>The grid lines the last traced paint drew (−1: none traced yet).</summary>
    Private _gridLinesTraced As Integer = -1

    Private Sub OnCanvasPaint(sender As Object, e As PaintEventArgs)
        Dim seconds = FramePaint.Paint(_painter, e.Graphics, _presenter, _canvas.ClientSize.Width, _canvas.ClientSize.Height)
        FrameStats?.RecordPaint(seconds)
        ' With --trace, how many grid lines the canvas drew, when that changes (GUI tests wait for it).
        If _trace IsNot Nothing Then
            Dim lines = _presenter.GridLines().Count
            If lines <> _gridLinesTraced Then
                _gridLinesTraced = lines
                _trace("canvas grid " & lines & " lines")
            End If
        End If
    End Sub

    Private Shared Function ToPointer(b As MouseButtons) As PointerButton
        Select Case b
            Case MouseButtons.Left : Return PointerButton.Left
            Case MouseButtons.Right : Return PointerButton.Right
            Case MouseButtons.Middle : Return PointerButton.Middle
            Case Else : Return PointerButton.None
        End Select
    End Function

    Private Sub OnCanvasMouseDown(sender As Object, e As MouseEventArgs)
        Act(Sub() _presenter.PointerDown(ToPointer(e.Button), e.X, e.Y))
    End Sub

    Private Sub OnCanvasMouseMove(sender As Object, e As MouseEventArgs)
        Act(Sub() _presenter.PointerMove(e.X, e.Y))
    End Sub

    Private Sub OnCanvasMouseUp(sender As Object, e As MouseEventArgs)
        Act(Sub() _presenter.PointerUp(ToPointer(e.Button), e.X, e.Y))
    End Sub

    Public Sub ShowMessage(text As String) Implements ISimulationView.ShowMessage
        If _presenter Is Nothing Then Return
        ' No message: a quiet reminder of what the mouse does, in grey rather than highlighted.
        Dim quiet = String.IsNullOrEmpty(text)
        Dim theme = _presenter.Theme
        Dim shown = If(quiet, SimulationPresenter.MouseHint, text)
        If _message.Text <> shown Then _message.Text = shown
        _message.BackColor = ScenePainter.Rgb(If(quiet, theme.Panel, theme.MessageBack))
        _message.ForeColor = ScenePainter.Rgb(If(quiet, theme.HintText, theme.MessageText))
        ' The area keeps its height whatever the message, so nothing under it moves; a message longer
        ' than the area scrolls within it (the wheel over it).
        _message.Invalidate()
        _trace?.Invoke("message shown " & _message.Height & " px, needs " & _message.Needs & " px" & If(_message.Scrolls, ", scrolls", ""))
        ' With --trace, the layout after every message: GUI tests check that no control moved.
        If IsHandleCreated AndAlso _trace IsNot Nothing Then TraceLayout()
    End Sub

    Public Sub ShowSettings() Implements ISimulationView.ShowSettings
        If _presenter Is Nothing Then Return
        _updating = True
        Try
            Dim theme = _presenter.Theme
            _speed.Value = _presenter.SpeedIndex
            _speedLabel.Text = _presenter.SpeedText
            _gravity.Value = _presenter.GravityPosition
            _gravityLabel.Text = _presenter.GravityText
            _restitution.Value = _presenter.RestitutionPosition
            _restitutionLabel.Text = Fitted(_restitutionLabel, _presenter.RestitutionText)
            _pause.Text = _presenter.PauseText
            _pause.ForeColor = ScenePainter.Rgb(If(_presenter.IsPaused, If(theme.IsHighContrast, &H69F0AE, &H1B5E20), theme.Alert))
            _deleteMode.Text = _presenter.DeleteModeText
            _solver.Text = _presenter.SolverText
            _deleteMode.BackColor = ScenePainter.Rgb(If(_presenter.Mode = ClickMode.Delete, theme.AlertBack, theme.Button))
            Dim inputs = _presenter.Inputs
            _fixed.Checked = inputs.IsFixed
            _rectFixed.Checked = inputs.RectangleFixed
            ' One mass box serves every movable body: it is greyed only when every tool would make a fixed one.
            _mass.Enabled = Not (inputs.IsFixed AndAlso inputs.RectangleFixed)
            ' The tool in use is lit like Delete mode, so the teacher sees what the next click does.
            Dim link = _presenter.Mode = ClickMode.Link
            For Each tool In {(_addSpring, link AndAlso _presenter.LinkToolKind = LinkKind.Spring),
                              (_addRod, link AndAlso _presenter.LinkToolKind = LinkKind.Rod),
                              (_addString, link AndAlso _presenter.LinkToolKind = LinkKind.String),
                              (_addRamp, _presenter.Mode = ClickMode.Ramp),
                              (_addCorners, _presenter.Mode = ClickMode.Corners),
                              (_addLiquid, _presenter.Mode = ClickMode.Liquid)}
                tool.Item1.BackColor = ScenePainter.Rgb(If(tool.Item2, theme.MessageBack, theme.Button))
            Next
            _largeFonts.Checked = _presenter.LargeFonts
            _highContrast.Checked = _presenter.HighContrast
            _arrows.Checked = _presenter.ShowArrows
            _grid.Checked = _presenter.ShowGrid
            _momentumBoxes.Show()
        Finally
            _updating = False
        End Try
        TraceInputs()
        _canvas.Invalidate()
    End Sub

    ''' <summary>
    ''' <paramref name="text"/>, or, when it is wider than <paramref name="label"/>, the text without
    ''' its last part in brackets ("Restitution e = 0.90" for "… (1 = elastic)", which stays in its tip).
    ''' </summary>
    Private Function Fitted(label As Label, text As String) As String
        _kit.Tips.SetToolTip(label, text)
        Dim bracket = text.LastIndexOf("  (", StringComparison.Ordinal)
        If bracket < 0 OrElse label.Width <= 0 OrElse Measure(text, label.Font).Width <= label.Width - S(4) Then Return text
        Return text.Substring(0, bracket)
    End Function

    Public Sub ShowInputs() Implements ISimulationView.ShowInputs
        If _presenter Is Nothing Then Return
        _updating = True
        Try
            For Each field In _inputs
                Dim wanted = _presenter.Inputs(field.Key)
                If field.Value.Text <> wanted Then field.Value.Text = wanted
            Next
        Finally
            _updating = False
        End Try
        TraceInputs()
    End Sub

    ''' <summary>With --trace: what the text boxes hold now, read from the boxes themselves.</summary>
    Private Sub TraceInputs()
        If _trace Is Nothing Then Return
        _trace("inputs " & String.Join(" ", _inputs.Select(Function(f) f.Key.ToString() & "=[" & f.Value.Text & "]")))
    End Sub

    Public Sub ShowState() Implements ISimulationView.ShowState
        If _presenter Is Nothing Then Return
        _time.Show()
        Dim snap = _presenter.Snapshot
        ' Only the table on show is sized and repainted; the others when their tab is chosen.
        Dim shown = _tabs.SelectedIndex
        If shown >= 0 AndAlso shown < _tables.Count Then
            Dim list = _tables(shown)
            If list.VirtualListSize <> snap.RowCount(shown) Then list.VirtualListSize = snap.RowCount(shown)
            GrowColumns(list)
            list.Invalidate()
        ElseIf shown = _tables.Count Then
            If _linkList.VirtualListSize <> snap.LinkCount Then _linkList.VirtualListSize = snap.LinkCount
            GrowColumns(_linkList)
            _linkList.Invalidate()
        End If
        ' Two lines are kept for the totals whatever their length, so their growing never moves the tables.
        Dim totals = WrapTotals(snap.Totals, _totals.Width - S(8))
        If totals <> _totals.Text Then _totals.Text = totals
        If _presenter.IsPaused Then _trace?.Invoke("totals " & totals.Replace(Environment.NewLine, " / "))
        _canvas.Invalidate()
    End Sub

    ''' <summary>The totals' items on as few lines as fit, breaking only between items.</summary>
    Private Function WrapTotals(items As IReadOnlyList(Of String), width As Integer) As String
        Const gap As String = "     "
        Dim lines As New List(Of String)
        Dim line = ""
        For Each item In items
            Dim candidate = If(line.Length = 0, item, line & gap & item)
            If line.Length > 0 AndAlso Measure(candidate, _totals.Font).Width > width Then
                lines.Add(line)
                line = item
            Else
                line = candidate
            End If
        Next
        If line.Length > 0 Then lines.Add(line)
        Return String.Join(Environment.NewLine, lines)
    End Function

    ''' <summary>The window's font size with normal fonts at 96 dpi, points.</summary>
    Private Const NormalFontPoints As Double = 10.0
    ''' <summary>The window's font size with large fonts at 96 dpi, points.</summary>
    Private Const LargeFontPoints As Double = 14.0

    Public Sub ShowTheme() Implements ISimulationView.ShowTheme
        If _presenter Is Nothing Then Return
        Dim size = CSng(If(_presenter.LargeFonts, LargeFontPoints, NormalFontPoints) * _dpi.FontScale)
        Dim old = Font
        Font = New Font(FontFamily.GenericSansSerif, size)
        If old IsNot Nothing AndAlso Not ReferenceEquals(old, DefaultFont) Then old.Dispose()
        Dim bold As New Font(Font, FontStyle.Bold)
        For Each l In {_speedLabel, _gravityLabel, _restitutionLabel}
            l.Font = bold
        Next
        ApplyColours(_presenter.Theme)
        If IsHandleCreated Then
            ArrangeControls()
            TraceLayout()
        End If
        ShowMessage(_presenter.Message)
        ShowSettings()
        ShowState()
        For Each list In _tables
            list.Invalidate()
        Next
        _logList.Invalidate()
    End Sub

    ''' <summary>The theme on every control: high contrast darkens the whole window, not the canvas alone.</summary>
    Private Sub ApplyColours(theme As Theme)
        Dim panel = ScenePainter.Rgb(theme.Panel), text = ScenePainter.Rgb(theme.PanelText)
        BackColor = panel
        ForeColor = text
        _canvas.BackColor = ScenePainter.Rgb(theme.Background)
        _totals.BackColor = panel
        _totals.ForeColor = text
        _side.BackColor = panel
        _sideView.BackColor = panel
        For Each c As Control In _side.Controls
            c.ForeColor = text
            If TypeOf c Is Button Then
                Dim b = DirectCast(c, Button)
                b.BackColor = ScenePainter.Rgb(theme.Button)
                b.FlatStyle = If(theme.IsHighContrast, FlatStyle.Flat, FlatStyle.Standard)
                b.FlatAppearance.BorderColor = text
                b.FlatAppearance.BorderSize = If(theme.IsHighContrast, 2, 1)
                b.UseVisualStyleBackColor = Not theme.IsHighContrast
            ElseIf TypeOf c Is TextBox AndAlso c IsNot _message Then
                c.BackColor = ScenePainter.Rgb(theme.Field)
            ElseIf c IsNot _message Then
                c.BackColor = panel
            End If
        Next
        ' Mono paints the strip beside the tabs' headers in the tab control's own colour.
        _tabs.BackColor = panel
        _tabStripFill.BackColor = panel
        For Each page As TabPage In _tabs.TabPages
            page.BackColor = panel
            page.ForeColor = text
        Next
        For Each list In _tables.Concat({_linkList, _logList})
            list.BackColor = panel
            list.ForeColor = text
        Next
    End Sub

    Protected Overrides Sub Dispose(disposing As Boolean)
        If disposing Then
            _timer.Dispose()
            _lessonMenu?.Dispose()
            _solverMenu?.Dispose()
            DisposeLiquidMenu()
            _exportMenu?.Dispose()
            _measureMenu?.Dispose()
            _graphs?.Dispose()
            _forcesPage?.Dispose()
            _momentumBoxes?.Dispose()
            _cells?.Dispose()
            _time?.Dispose()
            _painter.Dispose()
            _kit.Dispose()
        End If
        MyBase.Dispose(disposing)
    End Sub
End Class
