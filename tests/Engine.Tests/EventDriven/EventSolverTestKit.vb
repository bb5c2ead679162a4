Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>Helpers shared by the event-driven solver's scenario tests.</summary>
Friend Module EventSolverTestKit
    ''' <summary>Attaches a fresh event-driven solver and returns it.</summary>
    Friend Function UseEventSolver(w As World) As EventDrivenSolver
        Dim s = DirectCast(SolverFactory.Create("event"), EventDrivenSolver)
        w.Solver = s
        Return s
    End Function

    ''' <summary>
    ''' Fails unless energy plus dissipated is no more than 1e-9 of |<paramref name="e0"/>| above
    ''' <paramref name="e0"/> (J, at the start) and no two bodies overlap by more than 1e-9 m: the laws of a run
    ''' with e &lt; 1, checked at the world's time now.
    ''' </summary>
    Friend Sub AssertNoEnergyGainNorOverlap(w As World, e0 As Double)
        Dim books = w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated
        Assert.True(books <= e0 + 0.000000001 * Math.Abs(e0), $"at t = {w.Time} s energy plus dissipated is {books} J, above {e0} J at the start")
        Dim depth = DeepestOverlap(w)
        Assert.True(depth <= 0.000000001, $"at t = {w.Time} s two bodies overlap by {depth} m")
    End Sub

    ''' <summary>
    ''' Attaches a fresh event-driven solver to <paramref name="w"/> and runs it as <see cref="RunChecked"/> does.
    ''' </summary>
    Friend Function RunEventSolverChecked(w As World, seconds As Double, stepSeconds As Double,
                                          Optional energy As EnergyLaw = Nothing, Optional maxOverlap As Double? = Nothing,
                                          Optional eachStep As Action(Of World) = Nothing,
                                          Optional stopWhen As Func(Of World, Boolean) = Nothing) As CheckedRun
        UseEventSolver(w)
        Return RunChecked(w, seconds, stepSeconds, energy, maxOverlap, eachStep, stopWhen)
    End Function

    ''' <summary>
    ''' Advances <paramref name="w"/> with the solver it has, <paramref name="stepSeconds"/> at a time, for
    ''' <paramref name="seconds"/> (a whole number of steps), and after every step fails unless its energy keeps
    ''' <paramref name="energy"/> (against the books at the start) and no two bodies overlap by more than
    ''' <paramref name="maxOverlap"/> m (<see cref="DeepestOverlap"/>); a law left out is not checked. Then
    ''' <paramref name="eachStep"/> runs (further checks of the step), and the run ends early where
    ''' <paramref name="stopWhen"/> is true. Returns the worst that was seen.
    ''' </summary>
    Friend Function RunChecked(w As World, seconds As Double, stepSeconds As Double,
                               Optional energy As EnergyLaw = Nothing, Optional maxOverlap As Double? = Nothing,
                               Optional eachStep As Action(Of World) = Nothing,
                               Optional stopWhen As Func(Of World, Boolean) = Nothing) As CheckedRun
        If w Is Nothing Then Throw New ArgumentNullException(NameOf(w))
        Dim steps = CInt(Math.Round(seconds / stepSeconds))
        If steps < 1 OrElse Math.Abs(steps * stepSeconds - seconds) > 0.000000001 * seconds Then
            Throw New ArgumentException($"{seconds} s is not a whole number of steps of {stepSeconds} s", NameOf(seconds))
        End If
        Dim countsDissipated = energy IsNot Nothing AndAlso energy.CountsDissipated
        Dim run As New CheckedRun(w, Books(w, countsDissipated))
        Dim e0 = run.StartEnergy
        Dim what = If(countsDissipated, "energy plus dissipated", "energy")
        For k = 1 To steps
            w.Advance(stepSeconds)
            run.Steps = k
            If energy IsNot Nothing Then
                Dim now = Books(w, countsDissipated)
                Dim gain = now - e0
                run.MostGained = Math.Max(run.MostGained, gain)
                run.MostLost = Math.Max(run.MostLost, -gain)
                Assert.True(gain <= energy.MaxGain * Math.Abs(e0), $"at t = {w.Time} s {what} is {now} J, above {e0} J at the start by {gain / Math.Abs(e0):G3} of it")
                If Not Double.IsPositiveInfinity(energy.MaxLoss) Then
                    Assert.True(-gain <= energy.MaxLoss * Math.Abs(e0), $"at t = {w.Time} s {what} is {now} J, below {e0} J at the start by {-gain / Math.Abs(e0):G3} of it")
                End If
            End If
            If maxOverlap.HasValue Then
                Dim depth = DeepestOverlap(w)
                run.DeepestOverlap = Math.Max(run.DeepestOverlap, depth)
                Assert.True(depth <= maxOverlap.Value, $"at t = {w.Time} s two bodies overlap by {depth} m")
            End If
            eachStep?.Invoke(w)
            If stopWhen IsNot Nothing AndAlso stopWhen(w) Then Exit For
        Next
        Return run
    End Function

    ''' <summary>Kinetic plus potential energy (J), plus what was dissipated where <paramref name="countsDissipated"/>.</summary>
    Friend Function Books(w As World, countsDissipated As Boolean) As Double
        If w Is Nothing Then Throw New ArgumentNullException(NameOf(w))
        Return If(countsDissipated, w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated, w.KineticEnergy() + w.PotentialEnergy())
    End Function

    ''' <summary>The deepest overlap (m) between any two circles, or between a circle and a rectangle or wall, found with a grid.</summary>
    Friend Function DeepestOverlap(w As World) As Double
        Dim worst = 0.0
        Dim rMax = 0.0
        For Each c In w.Circles
            rMax = Math.Max(rMax, c.Radius)
        Next
        Dim cell = 2 * rMax
        Dim buckets As New Dictionary(Of (Long, Long), List(Of Circle))()
        For Each c In w.Circles
            Dim key = (CLng(Math.Floor(c.Position.X / cell)), CLng(Math.Floor(c.Position.Y / cell)))
            Dim list As List(Of Circle) = Nothing
            If Not buckets.TryGetValue(key, list) Then
                list = New List(Of Circle)()
                buckets(key) = list
            End If
            list.Add(c)
        Next
        For Each c In w.Circles
            Dim kx = CLng(Math.Floor(c.Position.X / cell)), ky = CLng(Math.Floor(c.Position.Y / cell))
            For ox = -1L To 1L
                For oy = -1L To 1L
                    Dim list As List(Of Circle) = Nothing
                    If Not buckets.TryGetValue((kx + ox, ky + oy), list) Then Continue For
                    For Each o In list
                        If o Is c Then Continue For
                        worst = Math.Max(worst, Collider.CircleCircle(c.Position, c.Radius, o.Position, o.Radius).Depth)
                    Next
                Next
            Next
            For Each r In w.Rectangles
                worst = Math.Max(worst, Collider.CircleRectangle(c.Position, c.Radius, r.Min, r.Max).Depth)
            Next
            If w.Walls AndAlso Not c.IsFixed Then
                worst = Math.Max(worst, c.Radius - c.Position.X)
                worst = Math.Max(worst, c.Position.X + c.Radius - w.Width)
                worst = Math.Max(worst, c.Radius - c.Position.Y)
                worst = Math.Max(worst, c.Position.Y + c.Radius - w.Height)
            End If
        Next
        Return worst
    End Function

    Friend Function Relative(actual As Double, expected As Double) As Double
        Return Math.Abs(actual - expected) / Math.Max(Math.Abs(expected), 1.0E-300)
    End Function
End Module

''' <summary>
''' What a checked run's energy may do: kinetic plus potential, plus what was dissipated where
''' <see cref="CountsDissipated"/>, may rise above its start e0 by <see cref="MaxGain"/> of |e0| at most and fall
''' below it by <see cref="MaxLoss"/> of |e0| at most.
''' </summary>
Friend NotInheritable Class EnergyLaw
    Friend Sub New(countsDissipated As Boolean, maxGain As Double, maxLoss As Double)
        Me.CountsDissipated = countsDissipated
        Me.MaxGain = maxGain
        Me.MaxLoss = maxLoss
    End Sub

    Friend ReadOnly Property CountsDissipated As Boolean
    Friend ReadOnly Property MaxGain As Double
    Friend ReadOnly Property MaxLoss As Double

    ''' <summary>Energy plus dissipated never above the start by more than <paramref name="relative"/> of it; any fall allowed.</summary>
    Friend Shared Function NeverGained(relative As Double) As EnergyLaw
        Return New EnergyLaw(True, relative, Double.PositiveInfinity)
    End Function

    ''' <summary>Energy plus dissipated within <paramref name="relative"/> of the start, either way.</summary>
    Friend Shared Function PlusDissipatedKept(relative As Double) As EnergyLaw
        Return New EnergyLaw(True, relative, relative)
    End Function

    ''' <summary>Kinetic plus potential energy alone within <paramref name="relative"/> of the start, either way.</summary>
    Friend Shared Function Kept(relative As Double) As EnergyLaw
        Return New EnergyLaw(False, relative, relative)
    End Function
End Class

''' <summary>The worst that a checked run saw (see <see cref="EventSolverTestKit.RunChecked"/>).</summary>
Friend NotInheritable Class CheckedRun
    Friend Sub New(world As World, startEnergy As Double)
        Me.World = world
        Me.StartEnergy = startEnergy
    End Sub

    ''' <summary>The world that was run, in its state at the end.</summary>
    Friend ReadOnly Property World As World
    ''' <summary>The books at the start (J): kinetic plus potential, plus dissipated where the law counts it.</summary>
    Friend ReadOnly Property StartEnergy As Double
    ''' <summary>How many steps were taken.</summary>
    Friend Property Steps As Integer
    ''' <summary>The most the books rose above the start after a step (J; 0 where never above or not checked).</summary>
    Friend Property MostGained As Double
    ''' <summary>The most the books fell below the start after a step (J; 0 where never below or not checked).</summary>
    Friend Property MostLost As Double
    ''' <summary>The deepest overlap after a step (m; 0 where overlaps were not checked).</summary>
    Friend Property DeepestOverlap As Double
End Class
