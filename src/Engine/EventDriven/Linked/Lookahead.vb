Option Strict On

''' <summary>
''' How far ahead an integrated motion has looked, and how it looks further. It looks first as far as its
''' integrator's first step; each time the end of that stretch is reached it looks on as far again as it has come
''' from its start, so the stretch doubles, but never more than <see cref="LongestStretchSeconds"/> at once. Its
''' bodies' contact searches stop at <see cref="EndTimeSeconds"/>, so a stiff spring's group, made anew at each
''' collision, is integrated only as far as the next collision needs, not a whole horizon ahead for a stretch that
''' collision throws away.
''' </summary>
Friend NotInheritable Class Lookahead
    ''' <summary>The longest stretch looked at once, s.</summary>
    Friend Const LongestStretchSeconds As Double = 0.1

    Private ReadOnly _startTimeSeconds As Double
    Private ReadOnly _firstStepSeconds As Double
    Private _endTimeSeconds As Double

    ''' <summary>
    ''' Looks ahead of a motion that starts at <paramref name="startTimeSeconds"/> (s, absolute) as far as its first
    ''' step, <paramref name="firstStepSeconds"/> (s).
    ''' </summary>
    Friend Sub New(startTimeSeconds As Double, firstStepSeconds As Double)
        _startTimeSeconds = startTimeSeconds
        _firstStepSeconds = firstStepSeconds
        _endTimeSeconds = startTimeSeconds + firstStepSeconds
    End Sub

    ''' <summary>The end of the stretch looked at so far (s, absolute): nothing happens there but looking further.</summary>
    Friend ReadOnly Property EndTimeSeconds As Double
        Get
            Return _endTimeSeconds
        End Get
    End Property

    ''' <summary>
    ''' The first step (s) of an integrator of springs whose fastest angular frequency is
    ''' <paramref name="fastestRadiansPerSecond"/> (rad/s; 0 for none): a hundredth of that spring's period, or 1 ms;
    ''' the error control corrects it at once.
    ''' </summary>
    Friend Shared Function FirstStepSeconds(fastestRadiansPerSecond As Double) As Double
        Return If(fastestRadiansPerSecond > 0, 0.06 / fastestRadiansPerSecond, 0.001)
    End Function

    ''' <summary>At <paramref name="timeSeconds"/> (s, absolute), the end reached: looks twice as far from the start (at least the first step more, at most <see cref="LongestStretchSeconds"/>).</summary>
    Friend Sub LookFurther(timeSeconds As Double)
        _endTimeSeconds = StretchEnd(_startTimeSeconds, timeSeconds, _firstStepSeconds)
    End Sub

    ''' <summary>
    ''' Where the stretch looked at from <paramref name="timeSeconds"/> ends (s, absolute), for a motion that started
    ''' at <paramref name="startTimeSeconds"/>: as far again as it has come since, at least
    ''' <paramref name="shortestStretchSeconds"/> and at most <see cref="LongestStretchSeconds"/>.
    ''' </summary>
    Friend Shared Function StretchEnd(startTimeSeconds As Double, timeSeconds As Double, shortestStretchSeconds As Double) As Double
        Return timeSeconds + Math.Min(LongestStretchSeconds, Math.Max(timeSeconds - startTimeSeconds, shortestStretchSeconds))
    End Function
End Class
