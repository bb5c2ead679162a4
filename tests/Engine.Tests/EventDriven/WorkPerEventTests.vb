Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The event solver's work per event does not grow with the number of bodies: the same gas (same
''' density, a box that grows with N) needs as many events per collision, and each event searches as
''' many grid cells, at N = 2 000 as at N = 20 000. These are counts, not timings, so they are exact
''' and repeatable; how the time per event behaves on a real machine (caches) is the benchmark's.
''' Both counts creep up towards a limit as the box grows (2.10 events per collision and 4.40 cells
''' per event at N = 200, 2.56 and 4.96 at N = 30 000): near the walls a ball has fewer cells to
''' search, and wall bounces are collisions that need no partner, and the walls' share of the box
''' shrinks as 1/√N. From N = 2 000 on that is a few per cent.
''' </summary>
Public Class WorkPerEventTests
    ''' <summary>Events per collision and cells searched per event over a stretch of the gas after its first predictions.</summary>
    Private Shared Function Work(count As Integer) As (EventsPerCollision As Double, CellsPerEvent As Double)
        Dim w = Scenarios.ElasticGas(count, 0.1)
        Dim s As New EventDrivenSolver()
        w.Solver = s
        ' The first predictions of every body are not per-event work, and the gas starts on a lattice:
        ' let every ball collide a few times first.
        Do While w.CollisionCount < 5L * count
            w.Advance(0.05)
        Loop
        Dim events0 = s.EventCount, cells0 = s.CellsSearched, collisions0 = w.CollisionCount
        Do While s.EventCount - events0 < 300_000
            w.Advance(0.05)
        Loop
        Dim events = s.EventCount - events0
        Return (events / CDbl(w.CollisionCount - collisions0), (s.CellsSearched - cells0) / CDbl(events))
    End Function

    <Fact>
    Public Sub TenTimesTheBodies_SameEventsPerCollision_SameCellsSearchedPerEvent()
        Dim small = Work(2000)
        Dim large = Work(20000)
        ' A search covers at most the 3 × 3 block, and an event searches for at most two bodies.
        Assert.InRange(small.CellsPerEvent, 1.0, 18.0)
        Assert.InRange(large.EventsPerCollision / small.EventsPerCollision, 0.9, 1.1)
        Assert.InRange(large.CellsPerEvent / small.CellsPerEvent, 0.9, 1.1)
    End Sub
End Class
