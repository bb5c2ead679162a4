Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Heat, cool, and balls added or removed at the gas's temperature, as PhET's Gas Properties has them.</summary>
Public Class GasControlsTests
    Private Shared Function Gas(n As Integer) As PresenterHarness
        Dim h As New PresenterHarness(Scenarios.ElasticGas(n))
        h.P.TogglePause()
        Return h
    End Function

    <Fact>
    Public Sub Heat_MultipliesTheTemperatureBy1Point25_CoolDividesByIt_AndUndoTakesItBack()
        Dim h = Gas(200)
        Dim kt0 = h.P.GasKT
        Assert.True(kt0 > 0)
        Dim speeds = h.P.World.Movables.Select(Function(b) b.Velocity.Length).ToArray()
        h.P.Heat()
        Assert.Equal(kt0 * SimulationPresenter.HeatFactor, h.P.GasKT, 9)
        ' Every speed grew by the same factor: the shape of the speeds' spread is kept.
        Dim grown = h.P.World.Movables.Select(Function(b) b.Velocity.Length).ToArray()
        For i = 0 To speeds.Length - 1
            Assert.Equal(speeds(i) * Math.Sqrt(SimulationPresenter.HeatFactor), grown(i), 9)
        Next
        Assert.StartsWith("Heated: the temperature, kT = mean KE, went from ", h.P.Message, StringComparison.Ordinal)
        h.P.Cool()
        h.P.Cool()
        Assert.Equal(kt0 / SimulationPresenter.HeatFactor, h.P.GasKT, 9)
        h.P.Undo()
        h.P.Undo()
        h.P.Undo()
        Assert.Equal(kt0, h.P.GasKT, 12)
    End Sub

    <Fact>
    Public Sub AddedBalls_AreLikeTheGassOwn_AtItsTemperature_AndFree()
        Dim h = Gas(100)
        Dim kt0 = h.P.GasKT
        Dim model = h.P.World.Circles(0)
        For k = 1 To 10
            h.P.AddBalls()
        Next
        Assert.Equal(200, h.P.World.Movables.Count)
        Dim added = h.P.World.Circles.Skip(100).ToList()
        Assert.True(added.All(Function(c) c.Radius = model.Radius AndAlso c.Mass = model.Mass AndAlso c.Color = model.Color))
        ' 100 new balls with velocities drawn at the gas's kT: their own mean KE is kT within what 200 random components allow (±25 %).
        Dim meanKE = added.Average(Function(c) c.KineticEnergy)
        Assert.InRange(meanKE, kt0 * 0.75, kt0 * 1.25)
        Assert.Null(Placement.FindProblem(h.P.World))
        Assert.StartsWith("Added 10 balls at the gas's temperature, kT = ", h.P.Message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub RemovedBalls_LeaveTheRest_AsTheyWere()
        Dim h = Gas(100)
        Dim before = h.P.World.Movables.ToDictionary(Function(b) b.Id, Function(b) b.Velocity)
        h.P.RemoveBalls()
        Assert.Equal(90, h.P.World.Movables.Count)
        For Each b In h.P.World.Movables
            Assert.Equal(before(b.Id), b.Velocity)
        Next
        h.P.RemoveBalls(500)
        Assert.Empty(h.P.World.Movables)
        h.P.RemoveBalls()
        Assert.Equal("There is no moving ball to remove.", h.P.Message)
        h.P.Heat()
        Assert.StartsWith("There is nothing to heat", h.P.Message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AFullBox_TakesAsManyAsFit_AndSaysSo()
        Dim w As New World(1, 1, 0.0, 1.0)
        w.Add(New Circle(New Vector(0.3, 0.3), 0.2, 1.0, New Vector(1, 0)))
        Dim h As New PresenterHarness(w)
        h.P.AddBalls(50)
        Dim n = h.P.World.Movables.Count
        Assert.InRange(n, 2, 10)
        Assert.Contains("there was room for only " & (n - 1), h.P.Message, StringComparison.Ordinal)
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub
End Class
