Option Strict On
Imports System.Drawing
Imports System.Drawing.Drawing2D
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>The main window: a thin view over <see cref="SimulationPresenter"/>.</summary>
Public NotInheritable Class MainForm
    Inherits Form

    Private ReadOnly _presenter As SimulationPresenter
    Private ReadOnly _canvas As New PictureBox()
    Private ReadOnly _timer As New Timer()
    Private ReadOnly _clock As Diagnostics.Stopwatch = Diagnostics.Stopwatch.StartNew()
    Private ReadOnly _pause As New Button()
    Private _lastTick As Double

    Public Sub New(presenter As SimulationPresenter)
        _presenter = presenter
        Text = "Collision Simulator"
        ClientSize = New Size(1100, 700)
        StartPosition = FormStartPosition.Manual
        Location = New Point(0, 0)
        BackColor = Color.White

        Dim side As New FlowLayoutPanel() With {.Dock = DockStyle.Right, .Width = 260, .FlowDirection = FlowDirection.TopDown, .Padding = New Padding(8)}
        _pause.Text = "Pause"
        _pause.Width = 120
        AddHandler _pause.Click, AddressOf OnPauseClick
        side.Controls.Add(_pause)

        _canvas.Dock = DockStyle.Fill
        _canvas.BackColor = Color.FromArgb(250, 250, 250)
        AddHandler _canvas.Paint, AddressOf OnCanvasPaint
        Controls.Add(_canvas)
        Controls.Add(side)

        _timer.Interval = 16
        AddHandler _timer.Tick, AddressOf OnTimerTick
        _timer.Start()
    End Sub

    Private Sub OnPauseClick(sender As Object, e As EventArgs)
        _presenter.IsPaused = Not _presenter.IsPaused
        _pause.Text = If(_presenter.IsPaused, "Resume", "Pause")
    End Sub

    Private Sub OnTimerTick(sender As Object, e As EventArgs)
        Dim now = _clock.Elapsed.TotalSeconds
        _presenter.Tick(now - _lastTick)
        _lastTick = now
        _canvas.Invalidate()
    End Sub

    Private Sub OnCanvasPaint(sender As Object, e As PaintEventArgs)
        Dim g = e.Graphics
        g.SmoothingMode = SmoothingMode.AntiAlias
        Dim world = _presenter.World
        Dim view = ViewTransform.Fit(world.Width, world.Height, _canvas.ClientSize.Width, _canvas.ClientSize.Height)
        Dim origin = view.ToScreen(New Vector(0, world.Height))
        Using border As New Pen(Color.Black, 2)
            g.DrawRectangle(border, CSng(origin.X), CSng(origin.Y), CSng(view.ToPixels(world.Width)), CSng(view.ToPixels(world.Height)))
        End Using
        For Each r In world.Rectangles
            Dim tl = view.ToScreen(New Vector(r.Min.X, r.Max.Y))
            Using b As New SolidBrush(Color.SlateGray)
                g.FillRectangle(b, CSng(tl.X), CSng(tl.Y), CSng(view.ToPixels(r.Width)), CSng(view.ToPixels(r.Height)))
            End Using
        Next
        For Each c In world.Circles
            Dim p = view.ToScreen(c.Position)
            Dim rad = view.ToPixels(c.Radius)
            Using b As New SolidBrush(If(c.IsFixed, Color.DimGray, Color.SteelBlue))
                g.FillEllipse(b, CSng(p.X - rad), CSng(p.Y - rad), CSng(2 * rad), CSng(2 * rad))
            End Using
        Next
    End Sub

    Protected Overrides Sub Dispose(disposing As Boolean)
        If disposing Then
            _timer.Dispose()
            _canvas.Dispose()
            _pause.Dispose()
        End If
        MyBase.Dispose(disposing)
    End Sub
End Class
