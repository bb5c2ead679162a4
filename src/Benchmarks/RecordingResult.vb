Option Strict On

''' <summary>What recording a run for rewind costs: the same gas run with and without it.</summary>
Friend NotInheritable Class RecordingResult
    ''' <summary>Balls in the gas.</summary>
    Public Property Balls As Integer
    ''' <summary>Simulated seconds of each run, s.</summary>
    Public Property SimulatedSeconds As Double
    ''' <summary>Events the event solver processed in one run.</summary>
    Public Property Events As Long
    ''' <summary>Median wall-clock time of a run without recording, s.</summary>
    Public Property PlainSeconds As Double
    ''' <summary>Median wall-clock time of a run recorded for rewind, s.</summary>
    Public Property RecordedSeconds As Double
    ''' <summary>Checkpoints the recorded run took.</summary>
    Public Property Checkpoints As Integer
    ''' <summary>Memory those checkpoints hold, bytes.</summary>
    Public Property Bytes As Long
    ''' <summary>Median wall-clock time of one checkpoint (the scene written out and the solver rebuilt), ms.</summary>
    Public Property CheckpointMs As Double
    ''' <summary>Events between two checkpoints in this gas.</summary>
    Public Property EventsBetween As Long
    ''' <summary>Runs of each kind.</summary>
    Public Property Repeats As Integer

    ''' <summary>
    ''' The overhead from its parts: one checkpoint's cost over the time the plain run takes for the
    ''' events between two checkpoints. Less noisy than the difference of two runs on a busy machine.
    ''' </summary>
    Public ReadOnly Property OverheadFromParts As Double
        Get
            Return CheckpointMs / 1000 / (EventsBetween * PlainSeconds / Events)
        End Get
    End Property

    ''' <summary>The extra time recording takes, as a fraction of the plain run's (0.05 = 5 %).</summary>
    Public ReadOnly Property Overhead As Double
        Get
            Return RecordedSeconds / PlainSeconds - 1
        End Get
    End Property
End Class
