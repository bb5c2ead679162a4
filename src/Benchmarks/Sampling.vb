Option Strict On

''' <summary>Runs a world in equal slices and lets a scene look at the state after each one.</summary>
Friend Module Sampling
    ''' <summary>
    ''' Advances <paramref name="world"/> by <paramref name="duration"/> seconds in slices of exactly
    ''' <paramref name="slice"/> seconds (then one shorter rest if need be) and calls
    ''' <paramref name="look"/> with the simulated time after each slice; stops early when it returns
    ''' False. Returns False when the budget ran out first.
    ''' </summary>
    ''' <remarks>
    ''' Each call is Advance(slice) with the same slice, never Advance(target − world.Time): the latter
    ''' carries the rounding of the world's clock (~1e-12 relative at t ≈ 3 s with 1/4000 s steps) into
    ''' the duration, which can make a stepping solver add a sliver step of ~1e-15 s.
    ''' </remarks>
    Public Function Run(world As World, duration As Double, slice As Double, look As Func(Of Double, Boolean), budget As RunBudget) As Boolean
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If look Is Nothing Then Throw New ArgumentNullException(NameOf(look))
        If budget Is Nothing Then Throw New ArgumentNullException(NameOf(budget))
        Dim whole = CLng(Math.Floor(duration / slice + 1.0E-9))
        For k = 1L To whole
            world.Advance(slice)
            If Not look(world.Time) Then Return True
            If budget.Expired Then Return False
        Next
        Dim rest = duration - whole * slice
        If rest > slice * 1.0E-9 Then
            world.Advance(rest)
            look(world.Time)
        End If
        Return True
    End Function

    ''' <summary>Advances by <paramref name="duration"/> in slices of about 50 ms; False when the budget ran out first.</summary>
    Public Function Advance(world As World, duration As Double, sampleStep As Double, budget As RunBudget) As Boolean
        Return Run(world, duration, SliceOf(sampleStep, 0.05), Function(t) True, budget)
    End Function

    ''' <summary>
    ''' A whole number of sample steps close to <paramref name="target"/> seconds: a stepping solver
    ''' must not be made to take a partial step in the middle of a run, or it would not be the run timed.
    ''' </summary>
    Public Function SliceOf(sampleStep As Double, target As Double) As Double
        Return Math.Max(1, Math.Round(target / sampleStep)) * sampleStep
    End Function

    ''' <summary>
    ''' Height of the vertex of the parabola through three equally spaced samples y0, y1, y2 (y1 the
    ''' largest). The exact apex for a parabolic flight, whatever the sampling phase.
    ''' </summary>
    Public Function ParabolaPeak(y0 As Double, y1 As Double, y2 As Double) As Double
        Dim curvature = 2 * y1 - y0 - y2
        If curvature <= 0 Then Return y1
        Return y1 + (y2 - y0) * (y2 - y0) / (8 * curvature)
    End Function
End Module
