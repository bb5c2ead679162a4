Option Strict On

''' <summary>
''' How long one frame may spend advancing the world, so that the whole frame (the advance, the
''' tables, the paint of the canvas) fits one refresh of a 60 Hz screen. The rest of the frame is
''' measured, not guessed: the frame's other work is the most it took in the last
''' <see cref="RememberedFrames"/> frames, so a slower paint (a bigger window, path traces on)
''' leaves the advance less time at once, and a paint spike is allowed for a while after it.
''' A scene that needs more than that shows slower time for the moment (and says so) rather than a
''' stutter of the whole picture.
''' </summary>
Public NotInheritable Class FrameBudget
    ''' <summary>The whole frame's target, s: under one refresh of a 60 Hz screen (1/60 s ≈ 16.7 ms).</summary>
    Public Const TargetSeconds As Double = 0.016
    ''' <summary>
    ''' Kept free of the advance, s: the last piece of an advance may run past the budget by a little
    ''' (the world is advanced in pieces, and the clock is read between them), and the frame has
    ''' small costs no one times (the timer's call, the window's own bookkeeping).
    ''' </summary>
    Public Const ReserveSeconds As Double = 0.002
    ''' <summary>
    ''' The least an advance gets, s, whatever the rest of the frame costs: a window so slow to paint
    ''' that nothing is left still moves the world, at a slower pace, instead of stopping it.
    ''' </summary>
    Public Const MinStepSeconds As Double = 0.004
    ''' <summary>Frames whose other work is remembered (half a second at 60 Hz).</summary>
    Public Const RememberedFrames As Integer = 30

    Private ReadOnly _other(RememberedFrames - 1) As Double
    Private _current As Integer

    ''' <summary>A new frame starts: its other work counts from zero, and the oldest remembered frame is forgotten.</summary>
    Public Sub NextFrame()
        _current = (_current + 1) Mod RememberedFrames
        _other(_current) = 0
    End Sub

    ''' <summary>The current frame spent <paramref name="seconds"/> (s) on work other than advancing the world (painting, tables).</summary>
    Public Sub AddOtherWork(seconds As Double)
        If Not (seconds > 0) OrElse Double.IsInfinity(seconds) Then Return
        _other(_current) += seconds
    End Sub

    ''' <summary>The most a remembered frame spent on other work, s.</summary>
    Public ReadOnly Property OtherWorkSeconds As Double
        Get
            Return _other.Max()
        End Get
    End Property

    ''' <summary>Wall-clock seconds the next advance may take: the target, less the reserve and the other work, and at least <see cref="MinStepSeconds"/>.</summary>
    Public ReadOnly Property StepSeconds As Double
        Get
            Return Math.Max(MinStepSeconds, TargetSeconds - ReserveSeconds - OtherWorkSeconds)
        End Get
    End Property
End Class
