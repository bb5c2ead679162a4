Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' Stiff damped springs settling far from the origin. At a spring's length its pull k (d − L) is the difference
    ''' of two nearly equal numbers, all rounding; the spring integrator's error control must take that rounding as
    ''' the floor of what a step can achieve (DormandPrince.TryStep), not chase it with ever shorter steps until it
    ''' gives up ("took more than 2000000 steps").
    ''' </summary>
    Public Class SpringRoundingTests
        ''' <summary>
        ''' Three balls (1, 1 and 2 g) in a line on two springs of 3·10⁴ N/m, each stretched 0.1 m and damped twice over
        ''' critical, g = 0, 10⁵ m from the origin: a group no closed form fits (IntegratedMotion). Over 2 s the springs
        ''' settle at their lengths, momentum stays zero, and energy plus what the damping took stays as it was.
        ''' </summary>
        <Fact>
        Public Sub ADampedChainOfStiffSprings_FarFromTheOrigin_SettlesWithItsBooksKept()
            Dim w As New World(200000, 200000, 0, 1)
            w.Solver = SolverFactory.Create("event")
            Dim origin As New Vector(99000, 99000)
            Dim a As New Circle(origin, 0.2, 0.001, Vector.Zero, "a")
            Dim b As New Circle(origin + New Vector(3.1, 0), 0.2, 0.001, Vector.Zero, "b")
            Dim c As New Circle(origin + New Vector(7.2, 0), 0.2, 0.002, Vector.Zero, "c")
            w.Add(a)
            w.Add(b)
            w.Add(c)
            Dim first = Link.CreateSpring(a, b, 30000, 3.0, damping:=15)
            Dim second = Link.CreateSpring(b, c, 30000, 4.0, damping:=15)
            w.Add(first)
            w.Add(second)
            EventSolverTestKit.RunChecked(w, 2, 0.1, EnergyLaw.PlusDissipatedKept(0.000000001))
            Assert.InRange((b.Position - a.Position).Length, 3.0 - 0.000000001, 3.0 + 0.000000001)
            Assert.InRange((c.Position - b.Position).Length, 4.0 - 0.000000001, 4.0 + 0.000000001)
            Dim momentum = a.Mass * a.Velocity + b.Mass * b.Velocity + c.Mass * c.Velocity
            Assert.True(momentum.Length <= 0.000000001, $"momentum {momentum} kg·m/s, from none")
        End Sub
    End Class
End Namespace
