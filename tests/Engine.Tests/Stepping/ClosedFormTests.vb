Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>Scenes with a textbook answer: 1D collisions, an oblique elastic hit, a projectile.</summary>
Public Class ClosedFormTests
    ' Head-on: the gap between the balls (3.8 m) closes and reopens well within 12 s for these speeds.
    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub HeadOn_ElasticAndInelastic_MatchNewtonsLaw(solver As String)
        Dim cases = {
            (m1:=1.0, u1:=2.0, m2:=1.0, u2:=0.0, e:=1.0),
            (m1:=2.0, u1:=3.0, m2:=1.0, u2:=-1.0, e:=1.0),
            (m1:=1.0, u1:=5.0, m2:=3.0, u2:=0.0, e:=0.5),
            (m1:=1.0, u1:=1.0, m2:=4.0, u2:=-0.5, e:=0.0),
            (m1:=1.0, u1:=1.0, m2:=1000000.0, u2:=0.0, e:=1.0),
            (m1:=1000000.0, u1:=1.0, m2:=1.0, u2:=0.0, e:=1.0)}
        For Each k In cases
            Dim w = TestSolvers.Run(Scenarios.HeadOn(k.m1, k.u1, k.m2, k.u2, k.e), solver)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) records.Add(r)
            w.Advance(12.0)
            Dim v1 = (k.m1 * k.u1 + k.m2 * k.u2 + k.m2 * k.e * (k.u2 - k.u1)) / (k.m1 + k.m2)
            Dim v2 = (k.m1 * k.u1 + k.m2 * k.u2 + k.m1 * k.e * (k.u1 - k.u2)) / (k.m1 + k.m2)
            Dim b1 = w.Circles(0), b2 = w.Circles(1)
            ' g = 0 and the contact normal is exactly x, so the impulse is the textbook one to rounding.
            Assert.Equal(v1, b1.Velocity.X, 9)
            Assert.Equal(v2, b2.Velocity.X, 9)
            Assert.Equal(0.0, b1.Velocity.Y, 12)
            Assert.Single(records)
            Assert.Equal(CollisionKind.CircleCircle, records(0).Kind)
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub ObliqueElasticHit_OfEqualMasses_LeavesAtRightAngles(solver As String)
        Const speed = 2.0, impact = 0.1, radius = 0.1
        Dim w = TestSolvers.Run(Scenarios.ObliqueHit(speed, impact, radius), solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        w.Advance(0.8) ' the hit is at about 0.41 s; the box walls are not reached by 0.8 s
        Assert.Single(records)
        Dim va = w.Circles(0).Velocity, vb = w.Circles(1).Velocity
        ' Equal masses, e = 1: v_a' = v_a − (v_a·n)n and v_b' = (v_a·n)n are perpendicular whatever n is.
        Assert.Equal(0.0, Vector.Dot(va, vb) / (va.Length * vb.Length), 9)
        Assert.Equal(speed * speed, va.LengthSquared + vb.LengthSquared, 9)
        Assert.Equal(speed, va.X + vb.X, 9)
        Assert.Equal(0.0, va.Y + vb.Y, 9)
        ' At contact the line of centres makes asin(b / 2r) with the x axis, so b leaves along it. A stepping
        ' solver finds the contact up to one step late (overlap ≤ v dt), which tilts the normal by about
        ' v dt / (2r cos θ); allow twice that.
        Dim theta = Math.Asin(impact / (2 * radius))
        Dim dt = If(w.Solver.TimeStep, 0.0)
        Dim tolerance = Math.Max(1.0E-9, 2 * speed * dt / (2 * radius * Math.Cos(theta)))
        Assert.InRange(Math.Atan2(-vb.Y, vb.X), theta - tolerance, theta + tolerance)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub Projectile_InFreeFlight_FollowsSuvat(solver As String)
        Const g = 9.81, t = 1.0
        Dim w = TestSolvers.Run(Scenarios.Projectile(speed:=10, angle:=Math.PI / 4, gravity:=g), solver)
        Dim ball = w.Circles(0)
        Dim p0 = ball.Position, u = ball.Velocity
        ' Frames of 1/60 s, as the app advances: each ends with a shortened sub-step.
        TestSolvers.Frames(w, t, 1.0 / 60)
        Assert.Equal(t, w.Time, 12)
        ' Semi-implicit Euler is first order: y_n = exact − ½ g dt t, so allow g dt t. Verlet (and an event
        ' solver) is exact under constant acceleration, so only rounding is allowed.
        Dim dt = If(w.Solver.TimeStep, 0.0)
        Dim tolerance = If(solver = "euler", g * dt * t, 1.0E-9)
        Assert.Equal(p0.X + u.X * t, ball.Position.X, 9)
        Assert.InRange(ball.Position.Y - (p0.Y + u.Y * t - 0.5 * g * t * t), -tolerance, tolerance)
        Assert.Equal(u.X, ball.Velocity.X, 9)
        Assert.Equal(u.Y - g * t, ball.Velocity.Y, 9)
        If solver = "euler" Then Assert.True(Math.Abs(ball.Position.Y - (p0.Y + u.Y * t - 0.5 * g * t * t)) > 0.1 * tolerance, "Euler's known first-order error should show")
    End Sub
End Class
