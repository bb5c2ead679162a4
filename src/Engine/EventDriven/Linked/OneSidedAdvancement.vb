Option Strict On

''' <summary>
''' Conservative advancement for the gap between two bodies that never rotate, with only a lower bound on its
''' curvature. The gap is φ(x(t)), with x the relative position of the two centres and φ the signed distance
''' to their Minkowski difference K (docs/links.md, "Boxes and polygons"). φ is convex (the signed distance to
''' a convex set is) and 1-Lipschitz, so for any time τ and its gradient n there (|n| = 1),
''' φ(x(t)) ≥ φ(x(τ)) + n·(x(t) − x(τ)), and with |ẍ| ≤ A over the interval (Taylor),
''' x(t) − x(τ) = ẋ(τ)s + (a remainder of size at most ½As²), s = t − τ. Together:
''' <code>d(t) ≥ d(τ) + ḋ(τ) s − ½ A s²</code>
''' with A the bound on the relative acceleration alone: the turning of the normal about K's corners only
''' ever raises the gap. That matters for sharp corners (boxes and polygons meeting, R = 0), where the turning
''' has no upper bound at all, so that <see cref="ConservativeAdvancement"/>'s two-sided bound (and its search
''' of a falling window, which needs one) cannot be used. Each step ends where this bound, or the first-order
''' one d(τ) − V s, could first reach the tolerance, so a step can land on a contact but never pass one; close to
''' a crossing the step is a Newton step taken from the safe side, so it converges quickly unless the gap
''' closes tangentially.
''' </summary>
Friend Module OneSidedAdvancement
    ''' <summary>
    ''' The first time in [<paramref name="startTime"/>, <paramref name="endTime"/>] (s) at which the gap falls to
    ''' <paramref name="tolerance"/> (m), given V ≥ |ḋ| (m/s) and A ≥ the relative acceleration (m/s²) over the interval.
    ''' </summary>
    Friend Function FirstContact(gap As IDistanceFunction, startTime As Double, endTime As Double, tolerance As Double,
                                 speedBound As Double, accelerationBound As Double, Optional maxEvaluations As Integer = 100000) As AdvancementResult
        Dim tau = startTime
        Dim d = gap.Distance(tau)
        Dim evaluations = 1
        If d <= tolerance Then Return New AdvancementResult(True, tau, tau, evaluations)
        Do
            Dim excess = d - tolerance
            Dim stepSize = If(speedBound > 0, excess / speedBound, Double.PositiveInfinity)
            Dim rate = gap.Rate(tau)
            If Not Double.IsNaN(rate) Then stepSize = Math.Max(stepSize, ConservativeAdvancement.SecondOrderStep(excess, rate, accelerationBound))
            Dim nextTime = tau + stepSize
            If nextTime > endTime Then Return New AdvancementResult(False, Double.PositiveInfinity, endTime, evaluations)
            ' A step too small to move the clock: the gap is within rounding of the tolerance, a contact.
            If nextTime <= tau Then Return New AdvancementResult(True, tau, tau, evaluations)
            If evaluations >= maxEvaluations Then Return New AdvancementResult(False, Double.PositiveInfinity, tau, evaluations)
            Dim dNext = gap.Distance(nextTime)
            evaluations += 1
            If dNext <= tolerance Then Return New AdvancementResult(True, nextTime, nextTime, evaluations)
            If nextTime = endTime Then Return New AdvancementResult(False, Double.PositiveInfinity, endTime, evaluations)
            tau = nextTime
            d = dNext
        Loop
    End Function
End Module
