Option Strict On

''' <summary>
''' How a stepping solver splits an advance into sub-steps: whole steps of dt, then one shorter last
''' step so the state lands on the exact requested time.
''' </summary>
Friend Module SubSteps
    ''' <summary>The number of sub-steps for <paramref name="duration"/> s with steps of at most <paramref name="dt"/> s.</summary>
    Friend Function Count(duration As Double, dt As Double) As Long
        ' The factor just below 1 stops a duration that is a whole number of steps give or take a rounding
        ' error from adding a last sliver step of ~1e-16 s (which would wreck Verlet's step ratio).
        Dim n = CLng(Math.Ceiling(duration / dt * (1 - 1.0E-12)))
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
