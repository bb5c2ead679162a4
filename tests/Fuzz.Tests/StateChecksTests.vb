Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports Xunit

''' <summary>Each state check fails on a state that breaks its invariant, and passes on one at its edge.</summary>
Public Class StateChecksTests
    Private Shared Function Box(Optional walls As Boolean = True) As World
        Return New World(4.0, 3.0, 9.81, 1.0, walls)
    End Function

    <Fact>
    Public Sub NotFinite_NamesTheBallWithANaNOrAnInfinity()
        Dim w = Box()
        Dim a As New Circle(New Vector(1, 1), 0.1, 1.0, id:="a")
        Dim b As New Circle(New Vector(2, 1), 0.1, 1.0, id:="b")
        w.Add(a)
        w.Add(b)
        Assert.Null(StateChecks.NotFinite(w))
        b.Position = New Vector(Double.NaN, 1)
        Assert.Contains("b", StateChecks.NotFinite(w), StringComparison.Ordinal)
        b.Position = New Vector(2, 1)
        a.Velocity = New Vector(0, Double.PositiveInfinity)
        Assert.StartsWith("a ", StateChecks.NotFinite(w), StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Outside_CatchesABallBeyondAWall_ButNotWithinTheTolerance()
        Dim w = Box()
        Dim a As New Circle(New Vector(1, 1), 0.1, 1.0, id:="a")
        w.Add(a)
        a.Position = New Vector(4.0 - 0.1 + 0.0000000005, 1) ' half the tolerance past the right wall
        Assert.Null(StateChecks.Outside(w))
        a.Position = New Vector(4.0 - 0.1 + 0.000001, 1)
        Assert.Contains("right wall", StateChecks.Outside(w), StringComparison.Ordinal)
        a.Position = New Vector(1, 0.05) ' 5 cm through the floor
        Assert.Contains("floor by 0.05", StateChecks.Outside(w), StringComparison.Ordinal)
        Dim open = Box(walls:=False)
        Dim b As New Circle(New Vector(-7, 1), 0.1, 1.0, id:="b")
        open.Add(b)
        Assert.Null(StateChecks.Outside(open))
    End Sub

    <Fact>
    Public Sub CentreInside_CatchesACentreInARectangleOrAFixedCircle()
        Dim w = Box()
        Dim r As New Rectangle(New Vector(1, 0), 1.0, 1.0, "r")
        Dim peg = Circle.CreateFixed(New Vector(3, 2), 0.3, "peg")
        Dim a As New Circle(New Vector(1.5, 1.2), 0.2, 1.0, id:="a")
        w.Add(r)
        w.Add(peg)
        w.Add(a)
        Assert.Null(StateChecks.CentreInside(w)) ' resting exactly on the top face
        a.Position = New Vector(1.5, 1.0) ' centre on the face: in by a radius, no further
        Assert.Null(StateChecks.CentreInside(w))
        a.Position = New Vector(1.5, 0.99)
        Assert.Contains("rectangle r", StateChecks.CentreInside(w), StringComparison.Ordinal)
        a.Position = New Vector(3.1, 2.1)
        Assert.Contains("fixed circle peg", StateChecks.CentreInside(w), StringComparison.Ordinal)
        a.Position = New Vector(3.0, 2.5) ' touching the peg from above
        Assert.Null(StateChecks.CentreInside(w))
    End Sub

    <Fact>
    Public Sub Overlap_CatchesTheDeepestPairThatCollides()
        Dim w = Box()
        Dim r As New Rectangle(New Vector(1, 0), 1.0, 1.0, "r")
        Dim f1 = Circle.CreateFixed(New Vector(3, 2), 0.3, "f1")
        Dim f2 = Circle.CreateFixed(New Vector(3.2, 2), 0.3, "f2") ' fixed bodies may overlap each other
        Dim a As New Circle(New Vector(0.4, 0.5), 0.2, 1.0, id:="a")
        Dim b As New Circle(New Vector(0.8, 0.5), 0.2, 1.0, id:="b") ' touching a, and touching r's left face
        w.Add(r)
        w.Add(f1)
        w.Add(f2)
        w.Add(a)
        w.Add(b)
        Assert.Null(StateChecks.Overlap(w))
        b.Position = New Vector(0.7999, 0.5)
        Assert.Contains("a and b overlap by 0.0001", StateChecks.Overlap(w), StringComparison.Ordinal)
        b.Position = New Vector(0.85, 0.5) ' 5 cm into r, clear of a
        Assert.Contains("rectangle r overlap by 0.05", StateChecks.Overlap(w), StringComparison.Ordinal)
        b.Position = New Vector(0.9, 1.5)
        a.Position = New Vector(3, 2.5 - 0.003)
        Assert.Contains("f1 and a overlap by 0.003", StateChecks.Overlap(w), StringComparison.Ordinal)
    End Sub


    <Fact>
    Public Sub Energy_CatchesAGain_ButNotALossOrTheAllowance()
        Dim w = Box()
        Dim a As New Circle(New Vector(1, 1), 0.1, 2.0, New Vector(3, 0), "a")
        w.Add(a)
        Dim budget As New EnergyBudget(w)
        Assert.Equal(0.5 * 2 * 9 + 2 * 9.81 * 1, budget.Start, 12)
        Assert.Null(budget.Check(w))
        a.Position = New Vector(1, 0.5) ' lower: a loss
        Assert.Null(budget.Check(w))
        a.Position = New Vector(1, 1 + 0.0000000005) ' raised by half the start's allowed lift
        Assert.Null(budget.Check(w))
        a.Position = New Vector(1, 1.001) ' raised by a millimetre: 0.0196 J from nothing
        Assert.Contains("energy grew", budget.Check(w), StringComparison.Ordinal)
        a.Position = New Vector(1, 1)
        a.Velocity = New Vector(3.00001, 0) ' 6.7e-6 of the energy
        Assert.NotNull(budget.Check(w))
    End Sub

    <Fact>
    Public Sub Energy_WithoutGravity_HasAScaleEvenWhenTheTotalIsSmall()
        Dim w As New World(4.0, 3.0, 0.0, 1.0, False)
        Dim a As New Circle(New Vector(1, 1), 0.1, 1.0, New Vector(1, 0), "a")
        w.Add(a)
        Dim budget As New EnergyBudget(w)
        a.Velocity = New Vector(1 + 0.0000000001, 0) ' 2e-10 of the energy: rounding
        Assert.Null(budget.Check(w))
        a.Velocity = New Vector(1.000001, 0)
        Assert.NotNull(budget.Check(w))
    End Sub
End Class
