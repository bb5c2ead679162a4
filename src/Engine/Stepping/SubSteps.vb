Option Strict On

''' <summary>
''' How a stepping solver splits an advance into sub-steps: whole steps of dt, then one last step
''' (shorter, or longer by under a millionth of dt to absorb rounding) so the state lands on the exact
''' requested time.
''' </summary>
Friend Module SubSteps
    ''' <summary>A remainder below this fraction of a step is folded into the last step.</summary>
    Friend Const SliverFraction As Double = 0.000001

    ''' <summary>The number of sub-steps for <paramref name="duration"/> s with steps of about <paramref name="dt"/> s.</summary>
    Friend Function Count(duration As Double, dt As Double) As Long
        ' A remainder under a millionth of a step is rounding (an advance to k·S − t computed in floating
        ' point), not time to simulate: it is folded into the last whole step. A separate sliver step of
        ' ~1e-15 s would divide position rounding by 1e-15 in Verlet's velocity and wreck its step ratio.
        Dim n = CLng(Math.Ceiling(duration / dt - SliverFraction))
        Return Math.Max(1L, n)
    End Function

    ''' <summary>The length, s, of sub-step <paramref name="k"/> (1-based) of <paramref name="n"/>.</summary>
    Friend Function Length(k As Long, n As Long, duration As Double, dt As Double) As Double
        If k < n Then Return dt
        Return Math.Max(duration - (n - 1) * dt, 0.0)
    End Function

    ''' <summary>Time from the start of the advance to the end of sub-step <paramref name="k"/>, s.</summary>
    Friend Function EndOffset(k As Long, n As Long, duration As Double, dt As Double) As Double
        If k < n Then Return k * dt
        Return duration
    End Function
End Module
