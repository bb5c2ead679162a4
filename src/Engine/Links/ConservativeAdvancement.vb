Option Strict On

''' <summary>
''' The first time in [t₀, t₁] at which a smooth distance d(t) falls to a tolerance, found without
''' ever stepping over a contact, given rigorous bounds over the interval: |d'| ≤ V, and optionally
''' |d''| ≤ A together with d' itself.
''' <list type="bullet">
''' <item>From any time τ the distance cannot fall faster than V, so d(t) ≥ d(τ) − V (t − τ) and d stays
''' above the tolerance for a step (d(τ) − tol)/V.</item>
''' <item>With d'(τ) and A: d(t) ≥ d(τ) + d'(τ)(t − τ) − ½A(t − τ)² (Taylor with the remainder bounded),
''' safe up to the positive root of that parabola. The longer of the two safe steps is taken.</item>
''' </list>
''' Each step ends where the bound could first touch the tolerance, so a step can only land on a
''' contact, never beyond one: if d is at the tolerance there, that is the first contact exactly.
''' Steps shrink geometrically towards a crossing (and, with the second-order bound, also past a
''' near-miss: a graze costs a few dozen steps, not thousands). When d'(τ) &lt; 0 and A is known, d is
''' monotone for −d'(τ)/A more; one evaluation at the end of that window either proves the window
''' clear (a long safe step) or brackets the only crossing in it, which Brent's method then finds
''' to rounding. With V alone the steps converge linearly (by 1 − |d'|/V each) down to a time
''' resolution: a step that no longer moves t means d is within V·ulp(t) of the tolerance, a contact.
''' </summary>
Public Module ConservativeAdvancement
    ''' <summary>
    ''' The first time in [<paramref name="startTime"/>, <paramref name="endTime"/>] (s) at which
    ''' d ≤ <paramref name="tolerance"/> (m).
    ''' </summary>
    ''' <param name="distance">d(t), and d'(t) or NaN</param>
    ''' <param name="speedBound">V ≥ |d'(t)| over the interval, m/s</param>
    ''' <param name="accelerationBound">A ≥ |d''(t)| over the interval, m/s²; +∞ when unknown</param>
    ''' <param name="maxEvaluations">budget; when it runs out the result says how far the interval is proved clear</param>
    Public Function FirstContact(distance As IDistanceFunction, startTime As Double, endTime As Double, tolerance As Double,
                                 speedBound As Double, Optional accelerationBound As Double = Double.PositiveInfinity,
                                 Optional maxEvaluations As Integer = 100000) As AdvancementResult
        If distance Is Nothing Then Throw New ArgumentNullException(NameOf(distance))
        If Not (endTime >= startTime) Then Throw New ArgumentException("the interval must not end before it starts", NameOf(endTime))
        If Not (speedBound >= 0) Then Throw New ArgumentOutOfRangeException(NameOf(speedBound), "must be non-negative")
        If Not (accelerationBound >= 0) Then Throw New ArgumentOutOfRangeException(NameOf(accelerationBound), "must be non-negative (+∞ when unknown)")
        Dim secondOrder = accelerationBound < Double.PositiveInfinity
        Dim tau = startTime
        Dim d = distance.Distance(tau)
        Dim evaluations = 1
        If d <= tolerance Then Return New AdvancementResult(True, tau, tau, evaluations)
        Do
            Dim excess = d - tolerance
            Dim stepSize = If(speedBound > 0, excess / speedBound, Double.PositiveInfinity)
            If secondOrder Then
                Dim rate = distance.Rate(tau)
                If Not Double.IsNaN(rate) Then
                    stepSize = Math.Max(stepSize, SecondOrderStep(excess, rate, accelerationBound))
                    ' Falling: d is monotone on [τ, τ − d'/A]. Look at the end of that window.
                    If rate < 0 Then
                        Dim windowEnd = If(accelerationBound > 0, Math.Min(endTime, tau - rate / accelerationBound), endTime)
                        If windowEnd - tau > 2 * stepSize AndAlso evaluations < maxEvaluations Then
                            Dim dEnd = distance.Distance(windowEnd)
                            evaluations += 1
                            If dEnd <= tolerance Then
                                Dim root = PolishedRoot(distance, tolerance, tau, windowEnd, excess, dEnd - tolerance, evaluations)
                                Return New AdvancementResult(True, root, root, evaluations)
                            End If
                            ' Monotone and still above at the window's end: all of it is clear.
                            If windowEnd >= endTime Then Return New AdvancementResult(False, Double.PositiveInfinity, endTime, evaluations)
                            tau = windowEnd
                            d = dEnd
                            Continue Do
                        End If
                    End If
                End If
            End If
            Dim nextTime = tau + stepSize
            If nextTime > endTime Then Return New AdvancementResult(False, Double.PositiveInfinity, endTime, evaluations)
            If nextTime <= tau Then Return New AdvancementResult(True, tau, tau, evaluations)
            If evaluations >= maxEvaluations Then Return New AdvancementResult(False, Double.PositiveInfinity, tau, evaluations)
            Dim dNext = distance.Distance(nextTime)
            evaluations += 1
            ' The bound kept d above the tolerance before nextTime: a contact here is the first one.
            If dNext <= tolerance Then Return New AdvancementResult(True, nextTime, nextTime, evaluations)
            If nextTime = endTime Then Return New AdvancementResult(False, Double.PositiveInfinity, endTime, evaluations)
            tau = nextTime
            d = dNext
        Loop
    End Function

    ''' <summary>
    ''' <see cref="FirstContact(IDistanceFunction, Double, Double, Double, Double, Double, Integer)"/> with the
    ''' distance as a delegate and only the first-order bound.
    ''' </summary>
    Public Function FirstContact(distance As Func(Of Double, Double), startTime As Double, endTime As Double, tolerance As Double,
                                 speedBound As Double, Optional maxEvaluations As Integer = 100000) As AdvancementResult
        If distance Is Nothing Then Throw New ArgumentNullException(NameOf(distance))
        Return FirstContact(New DelegateDistance(distance, Nothing), startTime, endTime, tolerance, speedBound, Double.PositiveInfinity, maxEvaluations)
    End Function

    ''' <summary>
    ''' <see cref="FirstContact(IDistanceFunction, Double, Double, Double, Double, Double, Integer)"/> with the
    ''' distance and its rate as delegates and both bounds.
    ''' </summary>
    Public Function FirstContact(distance As Func(Of Double, Double), rate As Func(Of Double, Double), startTime As Double, endTime As Double,
                                 tolerance As Double, speedBound As Double, accelerationBound As Double,
                                 Optional maxEvaluations As Integer = 100000) As AdvancementResult
        If distance Is Nothing Then Throw New ArgumentNullException(NameOf(distance))
        Return FirstContact(New DelegateDistance(distance, rate), startTime, endTime, tolerance, speedBound, accelerationBound, maxEvaluations)
    End Function

    ''' <summary>The positive root s of excess + rate s − ½ A s² = 0 (+∞ when the parabola never gets there), without cancellation.</summary>
    Friend Function SecondOrderStep(excess As Double, rate As Double, accelerationBound As Double) As Double
        If accelerationBound = 0 Then Return If(rate < 0, excess / -rate, Double.PositiveInfinity)
        Dim root = Math.Sqrt(rate * rate + 2 * accelerationBound * excess)
        If rate <= 0 Then Return 2 * excess / (root - rate)
        Return (rate + root) / accelerationBound
    End Function

    ''' <summary>The single crossing of d = tol in [lo, hi] (d monotone there), to rounding, by Brent's method.</summary>
    Private Function PolishedRoot(distance As IDistanceFunction, tolerance As Double, lo As Double, hi As Double,
                                  excessLo As Double, excessHi As Double, ByRef evaluations As Integer) As Double
        Dim count = 0
        Dim root = ScalarRoot.Brent(Function(t)
                                        count += 1
                                        Return distance.Distance(t) - tolerance
                                    End Function, lo, hi, excessLo, excessHi)
        evaluations += count
        Return root
    End Function

    ''' <summary>Delegates seen as an <see cref="IDistanceFunction"/>.</summary>
    Private NotInheritable Class DelegateDistance
        Implements IDistanceFunction

        Private ReadOnly _distance As Func(Of Double, Double)
        Private ReadOnly _rate As Func(Of Double, Double)

        Public Sub New(distance As Func(Of Double, Double), rate As Func(Of Double, Double))
            _distance = distance
            _rate = rate
        End Sub

        Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
            Return _distance(time)
        End Function

        Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
            Return If(_rate Is Nothing, Double.NaN, _rate(time))
        End Function
    End Class
End Module
