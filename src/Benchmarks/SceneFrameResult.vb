Option Strict On

''' <summary>
''' What the app's frame benchmark gave for one lesson scene (--frame-benchmark galton|rope|cradle),
''' or why it did not run. Times are ms per frame over the whole timed span.
''' </summary>
Friend NotInheritable Class SceneFrameResult
    ''' <summary>The app's name of the scene: galton, rope or cradle.</summary>
    Public Property Scene As String = ""
    ''' <summary>The benchmark report's scene it is meant to be (see <see cref="FrameBenchmark.SceneRows"/>).</summary>
    Public Property ReportScene As String = ""
    ''' <summary>True when the app ran and every time below was read.</summary>
    Public Property Ran As Boolean
    ''' <summary>Frames timed.</summary>
    Public Property Frames As Integer
    ''' <summary>Simulated seconds the frames covered (less than frames ÷ 60 when time on screen lagged).</summary>
    Public Property SimulatedSeconds As Double = Double.NaN
    ''' <summary>The solver the app ran the scene with, as it names it.</summary>
    Public Property Solver As String = ""
    ''' <summary>One presenter step per frame, ms: median, 95th percentile, worst.</summary>
    Public Property StepMs As New FrameTimes
    ''' <summary>One paint per frame, ms.</summary>
    Public Property PaintMs As New FrameTimes
    ''' <summary>The whole frame (step + paint), ms.</summary>
    Public Property TotalMs As New FrameTimes
    ''' <summary>The frame time the app holds the scene to, ms.</summary>
    Public Property TargetMs As Double = Double.NaN
    ''' <summary>Frames whose step and paint took the target or longer.</summary>
    Public Property OverTargetFrames As Integer
    ''' <summary>Frames in which the presenter let time on screen lag (its per-frame budget ran out).</summary>
    Public Property SlowFrames As Integer
    ''' <summary>Simulated seconds the presenter's budget held back over the run: how far time on screen fell behind (NaN when the app did not say).</summary>
    Public Property LagSeconds As Double = Double.NaN
    ''' <summary>Bodies, links and the moving bodies' energy (J) of the app's scene at the start, to compare with the report's.</summary>
    Public Property Bodies As Integer
    Public Property Links As Integer
    Public Property EnergyJoules As Double = Double.NaN
    ''' <summary>The app's own JSON line, as printed.</summary>
    Public Property RawJson As String = ""
    ''' <summary>Why it did not run, or a remark.</summary>
    Public Property Note As String = ""
End Class
