Option Strict On

''' <summary>
''' What the integrated motions (<see cref="IntegratedMotion"/>, <see cref="DragMotion"/>,
''' <see cref="ConstrainedMotion"/>) share about their accepted steps: which step holds a time, and the quintic
''' that matches a coordinate's position, velocity and acceleration at both ends of a step (docs/links.md).
''' </summary>
Friend Module QuinticSteps
    ''' <summary>The step holding <paramref name="time"/> (s): the last whose start, in <paramref name="times"/>, is at or before it.</summary>
    Friend Function StepHolding(times As List(Of Double), time As Double) As Integer
        Dim lo = 0, hi = times.Count - 2
        Do While lo < hi
            Dim mid = (lo + hi + 1) \ 2
            If times(mid) <= time Then lo = mid Else hi = mid - 1
        Loop
        Return Math.Max(lo, 0)
    End Function

    ''' <summary>
    ''' Writes at <paramref name="c"/>(<paramref name="offset"/>) onwards the coefficients c₀…c₅ in s = (t − t₀)/h of
    ''' the quintic with position p, velocity v·h and acceleration a·h² given at s = 0 (p0, v0, a0) and s = 1 (p1, v1, a1).
    ''' The ends' positions enter only through their difference p1 − p0, taken first: a body far from the origin moving a
    ''' little in a short step would otherwise lose its motion to the rounding of 10 p0 and 10 p1 (a 56 t ball at 3.5 m
    ''' stepping a microsecond read its speed 3·10⁻⁸ m/s off, 0.04 J of its energy).
    ''' </summary>
    Friend Sub Fill(c As Double(), offset As Integer, p0 As Double, v0 As Double, a0 As Double, p1 As Double, v1 As Double, a1 As Double)
        Dim dp = p1 - p0
        c(offset) = p0
        c(offset + 1) = v0
        c(offset + 2) = 0.5 * a0
        c(offset + 3) = 10 * dp - 6 * v0 - 4 * v1 - 1.5 * a0 + 0.5 * a1
        c(offset + 4) = -15 * dp + 8 * v0 + 7 * v1 + 1.5 * a0 - a1
        c(offset + 5) = 6 * dp - 3 * v0 - 3 * v1 - 0.5 * a0 + 0.5 * a1
    End Sub

    ''' <summary>The coefficients <see cref="Fill"/> writes, as a new array.</summary>
    Friend Function Coefficients(p0 As Double, v0 As Double, a0 As Double, p1 As Double, v1 As Double, a1 As Double) As Double()
        Dim c(5) As Double
        Fill(c, 0, p0, v0, a0, p1, v1, a1)
        Return c
    End Function
End Module
