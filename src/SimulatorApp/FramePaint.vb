Option Strict On
Imports System.Diagnostics
Imports System.Drawing
Imports PhysicsEngine.Presentation

''' <summary>
''' One paint of the canvas as a frame does it: the window's painter, timed, and the time told to the
''' presenter, whose next frames leave room for it in their budget. The window's paint handler and the
''' frame benchmark both paint through here, so the benchmark times what the window does.
''' </summary>
Friend Module FramePaint
    ''' <summary>Paints the scene into <paramref name="g"/> (width × height px); returns the paint's time, s.</summary>
    Public Function Paint(painter As ScenePainter, g As Graphics, presenter As SimulationPresenter, width As Integer, height As Integer) As Double
        If painter Is Nothing Then Throw New ArgumentNullException(NameOf(painter))
        If presenter Is Nothing Then Throw New ArgumentNullException(NameOf(presenter))
        Dim start = Stopwatch.GetTimestamp()
        painter.Paint(g, presenter, width, height)
        Dim seconds = (Stopwatch.GetTimestamp() - start) / CDbl(Stopwatch.Frequency)
        presenter.NoteFrameWork(seconds)
        Return seconds
    End Function
End Module
