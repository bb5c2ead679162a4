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
