Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports Xunit

''' <summary>
''' The checks on scenes with boxes, polygons and links: the energy budget counts what the energy counts
''' (every movable body and every spring), the state checks look at boxes as well as balls, and a refusal
''' is told from a failure by the world being put back exactly as it was.
''' </summary>
Public Class ShapeAndLinkChecksTests
    Private Shared Function Box(Optional walls As Boolean = True) As World
        Return New World(4.0, 3.0, 9.81, 1.0, walls)
    End Function

    <Fact>
    Public Sub EnergyBudget_OfABoxOnASpring_IsABillionthOfItsEnergyPlusItsLift()
        Dim w = Box()
        ' A 2 kg box 1 m up (centre of mass at y = 1.1 m) moving at 3 m/s, on a spring stretched 0.5 m (k = 40 N/m).
        Dim b = Rectangle.CreateMovable(New Vector(1, 1), 0.2, 0.2, 2.0, New Vector(3, 0), "b")
        w.Add(b)
        w.Add(Link.CreateSpring(b, New Vector(1.1, 2.6), 40, 1.0))
        Dim kinetic = 0.5 * 2.0 * 9.0
        Dim potential = 2.0 * 9.81 * 1.1
        Dim spring = 0.5 * 40 * 0.5 * 0.5
        Dim budget As New EnergyBudget(w)
        Assert.Equal(kinetic + potential + spring, budget.Start, 12)
        ' The spring's energy read to √(2 E k) · 4ε · 4 m (the container's larger side).
        Dim reading = Math.Sqrt(2 * (kinetic + potential + spring) * 40) * 4 * 2.220446049250313E-16 * 4
        Dim expected = EnergyBudget.RelativeTolerance * (kinetic + potential + spring) + 2.0 * 9.81 * StateChecks.Tolerance + reading
        Assert.True(Math.Abs(budget.Allowed - expected) <= 0.000000000001 * expected, $"allowed {budget.Allowed} J, expected {expected} J")
        ' Growth within the allowance passes; twice the allowance fails.
        b.Velocity = New Vector(Math.Sqrt(3 * 3 + 2 * 0.5 * budget.Allowed / 2.0), 0)
        Assert.Null(budget.Check(w))
        b.Velocity = New Vector(Math.Sqrt(3 * 3 + 2 * 2 * budget.Allowed / 2.0), 0)
        Assert.Contains("energy grew", budget.Check(w), StringComparison.Ordinal)
    End Sub

    ''' <summary>
    ''' A 8.6 mg box at 0.17 mm/s on a 57 kN/m spring at its rest length (g = 0): all of its 1.3·10⁻¹³ J in the spring
    ''' stretches it 2 nm, and ends rounded to 10⁻¹⁶ m read that energy only to about 10⁻²⁰ J, 10⁻⁷ of it. A growth that
    ''' size is allowed; one a hundred times the reading is not.
    ''' </summary>
    <Fact>
    Public Sub EnergyBudget_OfALightBoxOnAStiffSpring_AllowsWhatTheSpringCanBeReadTo()
        Dim w As New World(2.0, 0.5, 0.0, 0.5)
        Dim b = Rectangle.CreateMovable(New Vector(0.58, 0), 0.02, 0.016, 0.0000086, New Vector(-0.00017, 0), "b")
        w.Add(b)
        w.Add(Link.CreateSpring(b, New Vector(0.56, -0.065), 57296, (b.CentreOfMass - New Vector(0.56, -0.065)).Length))
        Dim budget As New EnergyBudget(w)
        Dim kinetic = 0.5 * 0.0000086 * 0.00017 * 0.00017
        Assert.True(budget.Allowed > 1000 * EnergyBudget.RelativeTolerance * kinetic, $"allowed {budget.Allowed} J")
        b.Velocity = New Vector(-Math.Sqrt(0.00017 * 0.00017 + 2 * 0.000000000000000000016 / 0.0000086), 0)
        Assert.Null(budget.Check(w))
        b.Velocity = New Vector(-Math.Sqrt(0.00017 * 0.00017 + 2 * 100 * budget.Allowed / 0.0000086), 0)
        Assert.Contains("energy grew", budget.Check(w), StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub NotFiniteAndOutside_LookAtBoxesToo()
        Dim w = Box()
        Dim b = Rectangle.CreateMovable(New Vector(1, 1), 0.4, 0.2, 1.0, Vector.Zero, "b")
        w.Add(b)
        Assert.Null(StateChecks.NotFinite(w))
        Assert.Null(StateChecks.Outside(w))
        b.Velocity = New Vector(Double.NaN, 0)
        Assert.StartsWith("b ", StateChecks.NotFinite(w), StringComparison.Ordinal)
        b.Velocity = Vector.Zero
        b.Position = New Vector(4.0 - 0.4 + 0.0000000005, 1) ' half the tolerance past the right wall
        Assert.Null(StateChecks.Outside(w))
        b.Position = New Vector(1, -0.001) ' 1 mm through the floor
        Assert.Contains("floor by 0.001", StateChecks.Outside(w), StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub WorldSnapshot_SeesAnyChangeToTheBit_AndNoneWhenNothingChanged()
        Dim w = Box()
        Dim a As New Circle(New Vector(1, 1), 0.1, 1.0, New Vector(0.5, 0), "a")
        w.Add(a)
        Dim snapshot As New WorldSnapshot(w)
        Assert.Null(snapshot.FirstDifference(w))
        a.Velocity = New Vector(Math.BitIncrement(0.5), 0)
        Assert.Contains("a moves at", snapshot.FirstDifference(w), StringComparison.Ordinal)
        a.Velocity = New Vector(0.5, 0)
        a.Position = New Vector(1, Math.BitDecrement(1.0))
        Assert.Contains("a is at", snapshot.FirstDifference(w), StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ABallBalancedOnAPegTop_RestsThere_BreakingNoInvariant_AndARefusalIsAFailure()
        ' A ball balanced on top of a fixed peg beside a pendulum: the peg's push is straight up and matches its
        ' weight, so it rests there (an unstable balance, but one), and nothing is broken.
        Const Scene As String = "{""format"": ""physics-scene/1"", ""world"": {""width"": 10, ""height"": 10, ""gravity"": 9.81, ""restitution"": 0.5, ""walls"": true}," &
            """bodies"": [{""id"": ""peg"", ""type"": ""circle"", ""x"": 3, ""y"": 2.5, ""radius"": 0.5, ""fixed"": true}," &
            "{""id"": ""c0"", ""type"": ""circle"", ""x"": 3, ""y"": 3.1, ""radius"": 0.1, ""mass"": 1, ""vx"": 0, ""vy"": 0}," &
            "{""id"": ""bob"", ""type"": ""circle"", ""x"": 8, ""y"": 8, ""radius"": 0.05, ""mass"": 1, ""vx"": 0, ""vy"": 0}]," &
            """links"": [{""id"": ""l1"", ""type"": ""rod"", ""a"": ""bob"", ""at"": [8, 9]}]}"
        Dim outcome = SceneRunner.Run(Scene, "event", 1.0, 0.05, 60)
        Assert.True(outcome.Violations.Count = 0, String.Join("; ", outcome.Violations))
        Assert.True(outcome.Completed)
        Assert.Contains(Invariants.SolverRefused, Invariants.All)
        Assert.Equal("FAIL ", Campaign.LinePrefix(Invariants.SolverRefused))
        Assert.Equal("FAIL ", Campaign.LinePrefix(Invariants.Overlap))
    End Sub
End Class
