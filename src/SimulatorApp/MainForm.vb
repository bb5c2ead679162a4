Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The main window: a thin view over <see cref="SimulationPresenter"/>. Its handlers forward the
''' teacher's actions to the presenter; what to show comes back through <see cref="ISimulationView"/>.
''' </summary>
Partial Friend NotInheritable Class MainForm
    Inherits Form
    Implements ISimulationView

    Public Const Title As String = "Collision Simulator"
    ''' <summary>Frames between refreshes of the tables and totals (about 10 per second).</summary>
    Private Const TableEvery As Integer = 6

    Private Shared ReadOnly BlankRow As String() = New String(9) {}
    Private Shared ReadOnly LogSamples As String() = {
        "00.000", "green ↔ wall:bottom", "blue: 4.17 → 4.15, green: 2.70 → 2.58", "100.00 → 100.00", "100%",
        "(-14.37, -17.94) → (-14.37, -17.94)  (green only: wall:bottom is fixed, p not conserved)"}

    Private ReadOnly _presenter As SimulationPresenter
    Private ReadOnly _painter As New ScenePainter()
    Private ReadOnly _trace As Action(Of String)
    Private ReadOnly _timer As New Timer()
    Private ReadOnly _clock As Diagnostics.Stopwatch = Diagnostics.Stopwatch.StartNew()
    Private _lastTick As Double
    Private _frame As Long
    Private _updating As Boolean
    Private _logVersion As Long = -1

    Private ReadOnly _canvas As New PictureBox()
    Private ReadOnly _totals As New Label()
    Private ReadOnly _tabs As New TabControl()
    Private ReadOnly _circleTable As New BufferedListView()
    Private ReadOnly _rectangleTable As New BufferedListView()
    Private ReadOnly _logList As New BufferedListView()
    Private ReadOnly _side As New Panel()
    Private ReadOnly _message As New Label()
    Private ReadOnly _pause As New Button()
    Private ReadOnly _reset As New Button()
    Private ReadOnly _deleteMode As New Button()
    Private ReadOnly _speedLabel As New Label()
    Private ReadOnly _speed As New TrackBar()
    Private ReadOnly _gravityLabel As New Label()
    Private ReadOnly _gravity As New TrackBar()
    Private ReadOnly _gravityMarks As New List(Of Button)
    Private ReadOnly _restitutionLabel As New Label()
    Private ReadOnly _restitution As New TrackBar()
    Private ReadOnly _addCircleLabel As New Label()
    Private ReadOnly _radiusLabel As New Label()
    Private ReadOnly _radius As New TextBox()
    Private ReadOnly _massLabel As New Label()
    Private ReadOnly _mass As New TextBox()
    Private ReadOnly _fixed As New CheckBox()
    Private ReadOnly _addCircle As New Button()
    Private ReadOnly _addRectangleLabel As New Label()
    Private ReadOnly _widthLabel As New Label()
    Private ReadOnly _rectWidth As New TextBox()
    Private ReadOnly _heightLabel As New Label()
    Private ReadOnly _rectHeight As New TextBox()
    Private ReadOnly _addRectangle As New Button()
    Private ReadOnly _containerLabel As New Label()
    Private ReadOnly _boxWidthLabel As New Label()
    Private ReadOnly _boxWidth As New TextBox()
    Private ReadOnly _boxHeightLabel As New Label()
    Private ReadOnly _boxHeight As New TextBox()
    Private ReadOnly _resize As New Button()
    Private ReadOnly _largeFonts As New CheckBox()
    Private ReadOnly _highContrast As New CheckBox()
    Private ReadOnly _arrows As New CheckBox()
    Private ReadOnly _tutorial As New Button()
    Private ReadOnly _maths As New Button()
    Private ReadOnly _open As New Button()
    Private ReadOnly _save As New Button()

    ''' <param name="trace">receives one line per action when the app runs with --trace; Nothing otherwise</param>
    ''' <param name="store">scene files; Nothing disables Open and Save</param>
    Public Sub New(trace As Action(Of String), store As ISceneStore)
        _trace = trace
        SuspendLayout()
        AutoScaleDimensions = New SizeF(96.0F, 96.0F)
        AutoScaleMode = AutoScaleMode.Dpi
        Text = Title
        StartPosition = FormStartPosition.Manual
        Location = New Point(0, 0)
        ClientSize = New Size(1280, 800)
        MinimumSize = New Size(900, 600)
        KeyPreview = True
        BuildControls()
        ResumeLayout(False)

        _presenter = New SimulationPresenter(Me, store) With {.Trace = trace}
        ShowSettings()
        ShowBodies()
        ShowTheme()
        ShowMessage("")

        _timer.Interval = 16
        AddHandler _timer.Tick, AddressOf OnTimerTick
    End Sub

    ''' <summary>The presenter, for the frame benchmark's sake of painting the same way.</summary>
    Friend ReadOnly Property Presenter As SimulationPresenter
        Get
            Return _presenter
        End Get
    End Property

    Private Sub BuildControls()
        _canvas.BackColor = Color.White
        AddHandler _canvas.Paint, AddressOf OnCanvasPaint
        AddHandler _canvas.MouseDown, AddressOf OnCanvasMouseDown
        AddHandler _canvas.MouseMove, AddressOf OnCanvasMouseMove
        AddHandler _canvas.MouseUp, AddressOf OnCanvasMouseUp
        AddHandler _canvas.Resize, Sub(s, e) _presenter?.CanvasResized(_canvas.ClientSize.Width, _canvas.ClientSize.Height)
        Controls.Add(_canvas)

        _totals.TextAlign = ContentAlignment.MiddleLeft
        _totals.AutoEllipsis = True
        _totals.UseMnemonic = False
        Controls.Add(_totals)

        SetUpTable(_circleTable, BodyTable.CircleHeaders, AddressOf OnRetrieveCircle)
        SetUpTable(_rectangleTable, BodyTable.RectangleHeaders, AddressOf OnRetrieveRectangle)
        SetUpTable(_logList, CollisionLogEntry.Headers, AddressOf OnRetrieveLog)
        AddTab("Circles", _circleTable)
        AddTab("Rectangles", _rectangleTable)
        AddTab("Collision log", _logList)
        Controls.Add(_tabs)

        _side.AutoScroll = True
        Controls.Add(_side)
        _message.BackColor = Color.FromArgb(255, 248, 196)
        _message.ForeColor = Color.FromArgb(120, 20, 0)
        _message.BorderStyle = BorderStyle.FixedSingle
        _message.Padding = New Padding(4)
        _side.Controls.Add(_message)

        AddButton(_pause, "Pause", Sub() _presenter.TogglePause())
        AddButton(_reset, "Reset", Sub() _presenter.Reset())
        AddButton(_deleteMode, "Delete mode", Sub() _presenter.ToggleDeleteMode())

        AddLabel(_speedLabel, "")
        SetUpSlider(_speed, 0, SpeedSteps.Values.Count - 1, 1, Sub() _presenter.SetSpeedIndex(_speed.Value))
        AddLabel(_gravityLabel, "")
        SetUpSlider(_gravity, 0, CInt(GravityMark.Maximum * 100), 500, Sub() _presenter.SetGravity(_gravity.Value / 100.0))
        _gravity.SmallChange = 10
        _gravity.LargeChange = 100
        For Each mark In GravityMark.All
            Dim b As New Button()
            Dim value = mark.Value
            AddButton(b, mark.Name & " " & Units.Num(mark.Value), Sub() _presenter.SetGravity(value))
            _gravityMarks.Add(b)
        Next
        AddLabel(_restitutionLabel, "")
        SetUpSlider(_restitution, 0, 100, 10, Sub() _presenter.SetRestitution(_restitution.Value / 100.0))
        _restitution.LargeChange = 10

        AddLabel(_addCircleLabel, "Add a circle")
        AddLabel(_radiusLabel, "Radius (m)")
        _side.Controls.Add(_radius)
        AddLabel(_massLabel, "Mass (kg)")
        _side.Controls.Add(_mass)
        _fixed.Text = "Fixed"
        _side.Controls.Add(_fixed)
        AddButton(_addCircle, "Add circle", Sub() _presenter.BeginAddCircle(_radius.Text, _mass.Text, _fixed.Checked))

        AddLabel(_addRectangleLabel, "Add a rectangle (always fixed)")
        AddLabel(_widthLabel, "Width (m)")
        _side.Controls.Add(_rectWidth)
        AddLabel(_heightLabel, "Height (m)")
        _side.Controls.Add(_rectHeight)
        AddButton(_addRectangle, "Add rectangle", Sub() _presenter.BeginAddRectangle(_rectWidth.Text, _rectHeight.Text))

        AddLabel(_containerLabel, "Container")
        AddLabel(_boxWidthLabel, "Width (m)")
        _side.Controls.Add(_boxWidth)
        AddLabel(_boxHeightLabel, "Height (m)")
        _side.Controls.Add(_boxHeight)
        AddButton(_resize, "Resize", Sub() _presenter.ResizeContainer(_boxWidth.Text, _boxHeight.Text))

        AddCheck(_largeFonts, "Large fonts", Sub() _presenter.SetLargeFonts(_largeFonts.Checked))
        AddCheck(_highContrast, "High contrast", Sub() _presenter.SetHighContrast(_highContrast.Checked))
        AddCheck(_arrows, "Arrows", Sub() _presenter.SetShowArrows(_arrows.Checked))
        AddButton(_tutorial, "Tutorial", Sub() ShowHelp("Tutorial", HelpTexts.Tutorial))
        AddButton(_maths, "Maths used", Sub() ShowHelp("Maths used", HelpTexts.Maths))
        AddButton(_open, "Open…", AddressOf OnOpen)
        AddButton(_save, "Save…", AddressOf OnSave)
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
        label.TextAlign = ContentAlignment.MiddleLeft
        _side.Controls.Add(label)
    End Sub

    Private Sub AddButton(button As Button, text As String, action As Action)
        button.Text = text
        AddHandler button.Click, Sub(s, e) Act(action)
        _side.Controls.Add(button)
    End Sub

    Private Sub AddCheck(box As CheckBox, text As String, action As Action)
        box.Text = text
        AddHandler box.CheckedChanged, Sub(s, e) If Not _updating Then Act(action)
        _side.Controls.Add(box)
    End Sub

    Private Sub SetUpSlider(slider As TrackBar, min As Integer, max As Integer, tick As Integer, action As Action)
        slider.Minimum = min
        slider.Maximum = max
        slider.TickFrequency = tick
        slider.TickStyle = TickStyle.BottomRight
        AddHandler slider.ValueChanged, Sub(s, e) If Not _updating Then Act(action)
        _side.Controls.Add(slider)
    End Sub

    ''' <summary>Runs a teacher's action; anything unexpected becomes a message, never a crash.</summary>
    Private Sub Act(action As Action)
        Try
            action()
        Catch ex As ArgumentException
            ShowMessage("That did not work: " & ex.Message)
        Catch ex As InvalidOperationException
            ShowMessage("That did not work: " & ex.Message)
        End Try
        _canvas.Invalidate()
    End Sub

    Private Sub ShowHelp(title As String, topics As IReadOnlyList(Of HelpTopic))
        Dim f As New HelpForm(title & " — " & MainForm.Title, topics, Font)
        AddHandler f.FormClosed, Sub(s, e) f.Dispose()
        f.Show(Me)
        _trace?.Invoke("help " & title)
    End Sub

    Private Sub OnOpen()
        If Not _presenter.CanOpenAndSave Then
            _presenter.OpenScene(Nothing)
            Return
        End If
        Using d As New OpenFileDialog() With {.Filter = "Scene files (*.json)|*.json|All files (*.*)|*.*", .Title = "Open a scene"}
            If d.ShowDialog(Me) = DialogResult.OK Then _presenter.OpenScene(d.FileName)
        End Using
    End Sub

    Private Sub OnSave()
        If Not _presenter.CanOpenAndSave Then
            _presenter.SaveScene(Nothing)
            Return
        End If
        Using d As New SaveFileDialog() With {.Filter = "Scene files (*.json)|*.json", .Title = "Save the scene", .DefaultExt = "json", .AddExtension = True}
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

    Protected Overrides Sub OnKeyDown(e As KeyEventArgs)
        MyBase.OnKeyDown(e)
        If e IsNot Nothing AndAlso e.KeyCode = Keys.Escape Then
            Act(Sub() _presenter.CancelPlacement())
            e.Handled = True
        End If
    End Sub

    Protected Overrides Sub OnResize(e As EventArgs)
        MyBase.OnResize(e)
        If IsHandleCreated Then ArrangeControls()
    End Sub

    Private Sub OnTimerTick(sender As Object, e As EventArgs)
        Dim now = _clock.Elapsed.TotalSeconds
        Dim dt = now - _lastTick
        _lastTick = now
        _presenter.Tick(dt)
        _frame += 1
        _canvas.Invalidate()
        If _frame Mod TableEvery = 0 Then RefreshTables()
    End Sub

    Private Sub RefreshTables()
        _totals.Text = _presenter.TotalsText
        If _circleTable.VirtualListSize <> _presenter.World.Circles.Count OrElse _rectangleTable.VirtualListSize <> _presenter.World.Rectangles.Count Then ShowBodies()
        Select Case _tabs.SelectedIndex
            Case 0 : If Not _presenter.IsPaused OrElse _presenter.DraggedBody IsNot Nothing Then _circleTable.Invalidate()
            Case 1 : _rectangleTable.Invalidate()
            Case 2
                If _logVersion <> _presenter.Log.Version Then
                    _logVersion = _presenter.Log.Version
                    _logList.VirtualListSize = _presenter.Log.Count
                    _logList.Invalidate()
                End If
        End Select
    End Sub

    Private Sub OnRetrieveCircle(sender As Object, e As RetrieveVirtualItemEventArgs)
        Dim circles = _presenter.World.Circles
        If e.ItemIndex >= circles.Count Then
            e.Item = New ListViewItem(BlankRow)
            Return
        End If
        e.Item = Row(BodyTable.CircleRow(circles(e.ItemIndex)))
    End Sub

    Private Sub OnRetrieveRectangle(sender As Object, e As RetrieveVirtualItemEventArgs)
        Dim rects = _presenter.World.Rectangles
        If e.ItemIndex >= rects.Count Then
            e.Item = New ListViewItem(BlankRow)
            Return
        End If
        e.Item = Row(BodyTable.RectangleRow(rects(e.ItemIndex)))
    End Sub

    Private Sub OnRetrieveLog(sender As Object, e As RetrieveVirtualItemEventArgs)
        Dim log = _presenter.Log
        e.Item = New ListViewItem(If(e.ItemIndex < log.Count, log(e.ItemIndex).Cells(), BlankRow))
    End Sub

    ''' <summary>A table row whose colour cell is filled with the body's colour.</summary>
    Private Shared Function Row(cells As String()) As ListViewItem
        Dim item As New ListViewItem(cells) With {.UseItemStyleForSubItems = False}
        Dim colour = BodyColours.Parse(cells(1), -1)
        If colour >= 0 Then
            item.SubItems(1).BackColor = ScenePainter.Rgb(colour)
            item.SubItems(1).ForeColor = Color.White
        End If
        Return item
    End Function

    Private Sub OnCanvasPaint(sender As Object, e As PaintEventArgs)
        _painter.Paint(e.Graphics, _presenter, _canvas.ClientSize.Width, _canvas.ClientSize.Height)
    End Sub

    Private Shared Function ToPointer(b As MouseButtons) As PointerButton
        Select Case b
            Case MouseButtons.Left : Return PointerButton.Left
            Case MouseButtons.Right : Return PointerButton.Right
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
        ' No message: a quiet reminder of what the mouse does, in grey rather than on yellow.
        Dim quiet = String.IsNullOrEmpty(text)
        _message.Text = If(quiet, SimulationPresenter.MouseHint, text)
        _message.BackColor = If(quiet, SystemColors.Control, Color.FromArgb(255, 248, 196))
        _message.ForeColor = If(quiet, Color.DimGray, Color.FromArgb(120, 20, 0))
    End Sub

    Public Sub ShowSettings() Implements ISimulationView.ShowSettings
        If _presenter Is Nothing Then Return
        _updating = True
        Try
            Dim w = _presenter.World
            _speed.Value = _presenter.SpeedIndex
            _speedLabel.Text = "Speed: " & SpeedSteps.Label(_presenter.Speed)
            _gravity.Value = CInt(Math.Round(w.Gravity * 100))
            _gravityLabel.Text = "Gravity g = " & Units.Num(w.Gravity) & " m/s²"
            _restitution.Value = CInt(Math.Round(w.Restitution * 100))
            _restitutionLabel.Text = "Restitution e = " & Units.Num(w.Restitution) & "  (1 = elastic)"
            _pause.Text = If(_presenter.IsPaused, "▶ Resume", "❚❚ Pause")
            _pause.ForeColor = If(_presenter.IsPaused, Color.DarkGreen, Color.DarkRed)
            _deleteMode.Text = If(_presenter.Mode = ClickMode.Delete, "Delete mode: ON", "Delete mode")
            _deleteMode.BackColor = If(_presenter.Mode = ClickMode.Delete, Color.FromArgb(255, 205, 210), SystemColors.Control)
            Dim i = _presenter.Inputs
            _radius.Text = i.RadiusText
            _mass.Text = i.MassText
            _fixed.Checked = i.IsFixed
            _mass.Enabled = Not i.IsFixed
            _rectWidth.Text = i.WidthText
            _rectHeight.Text = i.HeightText
            _boxWidth.Text = i.ContainerWidthText
            _boxHeight.Text = i.ContainerHeightText
            _largeFonts.Checked = _presenter.LargeFonts
            _highContrast.Checked = _presenter.HighContrast
            _arrows.Checked = _presenter.ShowArrows
        Finally
            _updating = False
        End Try
        _canvas.Invalidate()
    End Sub

    Public Sub ShowBodies() Implements ISimulationView.ShowBodies
        If _presenter Is Nothing Then Return
        _circleTable.VirtualListSize = _presenter.World.Circles.Count
        _rectangleTable.VirtualListSize = _presenter.World.Rectangles.Count
        _circleTable.Invalidate()
        _rectangleTable.Invalidate()
        _totals.Text = _presenter.TotalsText
    End Sub

    Public Sub ShowTheme() Implements ISimulationView.ShowTheme
        If _presenter Is Nothing Then Return
        Dim size = If(_presenter.LargeFonts, 14.0F, 10.0F)
        Dim old = Font
        Font = New Font(FontFamily.GenericSansSerif, size)
        If old IsNot Nothing AndAlso Not ReferenceEquals(old, DefaultFont) Then old.Dispose()
        Dim bold As New Font(Font, FontStyle.Bold)
        For Each l In {_addCircleLabel, _addRectangleLabel, _containerLabel, _speedLabel, _gravityLabel, _restitutionLabel}
            l.Font = bold
        Next
        _canvas.BackColor = ScenePainter.Rgb(_presenter.Theme.Background)
        If IsHandleCreated Then
            ArrangeControls()
            TraceLayout()
        End If
        _canvas.Invalidate()
    End Sub

    Protected Overrides Sub Dispose(disposing As Boolean)
        If disposing Then
            _timer.Dispose()
            _painter.Dispose()
        End If
        MyBase.Dispose(disposing)
    End Sub
End Class
