Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The graph on show in a window of its own, as large as a projector needs: the tab under the
''' canvas is small, the more so with large fonts. It draws what the Graphs tab draws (the
''' presenter's <see cref="SimulationPresenter.CurrentGraph"/>), redrawn by the main window's clock.
''' </summary>
Friend NotInheritable Class GraphWindow
    Inherits Form

    Private ReadOnly _presenter As SimulationPresenter
    Private ReadOnly _scale As Double
    Private ReadOnly _box As New PictureBox() With {.Dock = DockStyle.Fill}

    Public Sub New(presenter As SimulationPresenter, font As Font, scale As Double, bounds As Drawing.Rectangle)
        _presenter = presenter
        _scale = scale
        AutoScaleMode = AutoScaleMode.None
        Text = "Graph — " & MainForm.Title
        Me.Font = font
        StartPosition = FormStartPosition.Manual
        KeyPreview = True
        Me.Bounds = bounds
        AddHandler _box.Paint, Sub(s, e) GraphPainter.Paint(e.Graphics, _presenter.CurrentGraph(), _presenter.Theme, Me.Font, _box.ClientSize.Width, _box.ClientSize.Height, _scale)
        AddHandler _box.Resize, Sub(s, e) _box.Invalidate()
        Controls.Add(_box)
    End Sub

    ''' <summary>Esc closes the window, as it closes every other secondary window.</summary>
    Protected Overrides Function ProcessCmdKey(ByRef msg As Message, keyData As Keys) As Boolean
        If keyData = Keys.Escape Then
            Close()
            Return True
        End If
        Return MyBase.ProcessCmdKey(msg, keyData)
    End Function

    ''' <summary>Draws the graph again (time went on, or another graph was chosen).</summary>
    Public Sub Redraw()
        _box.Invalidate()
    End Sub

    ''' <summary>Where the graph is drawn, on the screen.</summary>
    Public ReadOnly Property GraphBounds As Drawing.Rectangle
        Get
            Return New Drawing.Rectangle(_box.PointToScreen(Point.Empty), _box.ClientSize)
        End Get
    End Property
End Class
