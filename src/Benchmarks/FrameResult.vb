Option Strict On

''' <summary>What the app's frame benchmark gave, or why it did not run.</summary>
Friend NotInheritable Class FrameResult
    ''' <summary>True when the app ran and its numbers were read.</summary>
    Public Property Ran As Boolean
    ''' <summary>Circles in the scene.</summary>
    Public Property Circles As Integer
    ''' <summary>Median time of one physics step per frame, ms.</summary>
    Public Property StepMs As Double = Double.NaN
    ''' <summary>Median time to paint one frame, ms.</summary>
    Public Property PaintMs As Double = Double.NaN
    ''' <summary>The app's own JSON line, as printed.</summary>
    Public Property RawJson As String = ""
    ''' <summary>Why it did not run, or a remark.</summary>
    Public Property Note As String = ""
    ''' <summary>The same frames with the path traces, the centre of mass and the Σp arrow on; Nothing when the app printed no such row.</summary>
    Public Property Views As FrameResult
End Class
