Option Strict On

''' <summary>
''' Scenes with a known answer, built in one place so that the tests, the benchmark and the app's
''' presets use the same ones (Box2D's shared/ folder). Each returns a world with no solver yet.
''' </summary>
Public Module Scenarios
    ''' <summary>A ball of radius r dropped from rest with its lowest point h0 metres above the floor.</summary>
    Public Function BouncingBall(Optional dropHeight As Double = 1.0, Optional restitution As Double = 0.9,
                                 Optional gravity As Double = 9.81, Optional radius As Double = 0.05) As World
        Dim w As New World(1.0, dropHeight + 2 * radius + 1.0, gravity, restitution)
        w.Add(New Circle(New Vector(0.5, dropHeight + radius), radius, 1.0, id:="ball"))
        Return w
    End Function

    ''' <summary>A projectile launched from (x0, y0) at speed v0 and angle θ (rad) above the horizontal, in a large box.</summary>
    Public Function Projectile(Optional speed As Double = 10.0, Optional angle As Double = Math.PI / 4,
                               Optional gravity As Double = 9.81, Optional radius As Double = 0.05) As World
        Dim w As New World(20.0, 10.0, gravity, 1.0)
        Dim v = New Vector(speed * Math.Cos(angle), speed * Math.Sin(angle))
        w.Add(New Circle(New Vector(1.0, radius), radius, 1.0, v, "ball"))
        Return w
    End Function

    ''' <summary>
    ''' Two equal balls, g = 0, e = 1: "a" moves along +x at speed v0 and strikes "b", at rest, off-centre
    ''' with impact parameter b (m, less than 2r). They leave at 90° to each other.
    ''' </summary>
    Public Function ObliqueHit(Optional speed As Double = 2.0, Optional impactParameter As Double = 0.1,
                               Optional radius As Double = 0.1) As World
        Dim w As New World(4.0, 2.0, 0.0, 1.0)
        w.Add(New Circle(New Vector(1.0, 1.0 + impactParameter), radius, 1.0, New Vector(speed, 0), "a"))
        w.Add(New Circle(New Vector(2.0, 1.0), radius, 1.0, id:="b"))
        Return w
    End Function

    ''' <summary>
    ''' A head-on 1D collision on the x axis, g = 0, no walls: masses m1, m2 at speeds u1, u2 (m/s),
    ''' with restitution e.
    ''' </summary>
    Public Function HeadOn(m1 As Double, u1 As Double, m2 As Double, u2 As Double, restitution As Double,
                           Optional radius As Double = 0.1) As World
        Dim w As New World(10.0, 2.0, 0.0, restitution, walls:=False)
        w.Add(New Circle(New Vector(3.0, 1.0), radius, m1, New Vector(u1, 0), "1"))
        w.Add(New Circle(New Vector(7.0, 1.0), radius, m2, New Vector(u2, 0), "2"))
        Return w
    End Function

    ''' <summary>
    ''' Newton's cradle: five touching equal balls at rest in a row, g = 0, e = 1, and a sixth ("striker")
    ''' approaching the row from the left at v0 (m/s). No walls.
    ''' </summary>
    Public Function NewtonsCradle(Optional speed As Double = 1.0, Optional count As Integer = 5,
                                  Optional radius As Double = 0.1) As World
        Dim w As New World(10.0, 2.0, 0.0, 1.0, walls:=False)
        w.Add(New Circle(New Vector(1.0, 1.0), radius, 1.0, New Vector(speed, 0), "striker"))
        For i = 0 To count - 1
            w.Add(New Circle(New Vector(3.0 + 2 * radius * i, 1.0), radius, 1.0, id:="ball" & (i + 1).ToString(Globalization.CultureInfo.InvariantCulture)))
        Next
        Return w
    End Function

    ''' <summary>
    ''' "π from collisions": a light block (1 kg) between a wall on the left and a heavy block
    ''' (100^k kg) moving towards it, g = 0, e = 1. The number of collisions (block–block and
    ''' block–wall) is the first k + 1 digits of π: 31, 314, 3141, 31415 for k = 1 to 4.
    ''' </summary>
    Public Function PiCollisions(k As Integer) As World
        Dim w As New World(1000.0, 2.0, 0.0, 1.0)
        w.Add(New Circle(New Vector(2.0, 1.0), 0.5, 1.0, id:="small"))
        w.Add(New Circle(New Vector(5.0, 1.0), 0.5, Math.Pow(100, k), New Vector(-1.0, 0), "big"))
        Return w
    End Function

    ''' <summary>
    ''' An elastic gas: N equal circles (1 kg) in a square walled box with g = 0 and e = 1, at the given
    ''' packing fraction (circle area ÷ box area), on a jittered grid with random velocities
    ''' (components uniform in ±1 m/s). The same seed gives the same gas.
    ''' </summary>
    Public Function ElasticGas(count As Integer, Optional packingFraction As Double = 0.1,
                               Optional radius As Double = 0.01, Optional seed As Integer = 1) As World
        If count < 1 Then Throw New ArgumentOutOfRangeException(NameOf(count))
        If Not (packingFraction > 0 AndAlso packingFraction < 0.7) Then Throw New ArgumentOutOfRangeException(NameOf(packingFraction))
        Dim side = Math.Sqrt(count * Math.PI * radius * radius / packingFraction)
        Dim perRow = CInt(Math.Ceiling(Math.Sqrt(count)))
        Dim cell = side / perRow
        Dim w As New World(side, side, 0.0, 1.0)
        Dim rng As New Random(seed)
        Dim slack = Math.Max(0.0, cell / 2 - radius * 1.000001)
        For i = 0 To count - 1
            Dim cx = (i Mod perRow + 0.5) * cell + (rng.NextDouble() * 2 - 1) * slack
            Dim cy = (i \ perRow + 0.5) * cell + (rng.NextDouble() * 2 - 1) * slack
            Dim v = New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1)
            w.Add(New Circle(New Vector(cx, cy), radius, 1.0, v))
        Next
        Return w
    End Function

    ''' <summary>
    ''' A pile: N circles of mixed radius dropped into a walled box with restitution e and g = 9.81,
    ''' starting apart on a grid above the floor with small random velocities.
    ''' </summary>
    Public Function Pile(count As Integer, Optional restitution As Double = 0.3, Optional seed As Integer = 1) As World
        If count < 1 Then Throw New ArgumentOutOfRangeException(NameOf(count))
        Const r = 0.05
        Dim perRow = 20
        Dim rows = (count + perRow - 1) \ perRow
        Dim width = perRow * 2.5 * r
        Dim w As New World(width, rows * 2.5 * r + 1.0, 9.81, restitution)
        Dim rng As New Random(seed)
        For i = 0 To count - 1
            Dim radius = r * (0.8 + 0.2 * rng.NextDouble())
            Dim x = (i Mod perRow + 0.5) * 2.5 * r
            Dim y = 0.5 + (i \ perRow + 0.5) * 2.5 * r
            Dim v = New Vector(rng.NextDouble() - 0.5, rng.NextDouble() - 0.5)
            w.Add(New Circle(New Vector(x, y), radius, radius * radius * 1000.0, v))
        Next
        Return w
    End Function

    ''' <summary>
    ''' A hard mixed scene: <paramref name="count"/> balls whose radii run from 1 mm to 0.5 m (evenly
    ''' on a log scale), with masses spread over twelve orders of magnitude and speeds from 0.1 to
    ''' 10⁴ m/s in random directions, among four fixed rectangles (two standing partly outside the
    ''' container) and three fixed circles, g = 9.81, e = 1, in a walled box 3 m × 7 m. Fast small
    ''' balls bounce among large slow ones millions of times per simulated second: what a scene like
    ''' this costs per collision is what it measures. The same seed gives the same scene.
    ''' </summary>
    Public Function MixedSizes(Optional count As Integer = 60, Optional seed As Integer = 1) As World
        If count < 1 Then Throw New ArgumentOutOfRangeException(NameOf(count))
        Dim w As New World(3.0, 7.0, 9.81, 1.0)
        w.Add(New Rectangle(New Vector(-0.3, 1.0), 0.9, 0.4, "ledge"))
        w.Add(New Rectangle(New Vector(2.0, -0.5), 0.6, 1.5, "block"))
        w.Add(New Rectangle(New Vector(0.9, 3.2), 1.2, 0.15, "shelf"))
        w.Add(New Rectangle(New Vector(2.6, 5.0), 0.6, 0.3, "sill"))
        w.Add(Circle.CreateFixed(New Vector(0.8, 5.6), 0.25, "peg1"))
        w.Add(Circle.CreateFixed(New Vector(1.9, 2.2), 0.15, "peg2"))
        w.Add(Circle.CreateFixed(New Vector(0.5, 0.6), 0.1, "peg3"))
        Dim rng As New Random(seed)
        Dim placed = 0
        Dim tries = 0
        While placed < count AndAlso tries < 100000
            tries += 1
            Dim r = 0.001 * Math.Pow(500, rng.NextDouble())
            Dim p = New Vector(r + rng.NextDouble() * (w.Width - 2 * r), r + rng.NextDouble() * (w.Height - 2 * r))
            Dim clear = True
            For Each c In w.Circles
                If (c.Position - p).Length < c.Radius + r Then clear = False : Exit For
            Next
            For Each rect In w.Rectangles
                If clear AndAlso Collider.CircleRectangle(p, r, rect.Min, rect.Max).Depth > 0 Then clear = False
            Next
            If Not clear Then Continue While
            Dim density = Math.Pow(10, 8 * rng.NextDouble() - 4) ' kg/m²: masses over 10¹² with the radii
            Dim speed = 0.1 * Math.Pow(100000, rng.NextDouble())
            Dim angle = 2 * Math.PI * rng.NextDouble()
            w.Add(New Circle(p, r, density * Math.PI * r * r, New Vector(speed * Math.Cos(angle), speed * Math.Sin(angle))))
            placed += 1
        End While
        Return w
    End Function

    ''' <summary>
    ''' A ball of radius r released at rest touching a fixed frictionless ramp of length 4 m at angle θ
    ''' (rad) to the horizontal, 0.3 m down from its top end. It slides with a = g sin θ along the slope.
    ''' </summary>
    Public Function RampSlide(Optional angle As Double = Math.PI / 6, Optional gravity As Double = 9.81,
                              Optional radius As Double = 0.1) As World
        Const length = 4.0
        Dim top = New Vector(0.5, 0.5 + length * Math.Sin(angle))
        Dim bottom = New Vector(0.5 + length * Math.Cos(angle), 0.5)
        Dim w As New World(bottom.X + 1.0, top.Y + 1.0, gravity, 0.5)
        w.Add(New Segment(top, bottom, "ramp"))
        Dim down = New Vector(Math.Cos(angle), -Math.Sin(angle))
        Dim up = New Vector(Math.Sin(angle), Math.Cos(angle))
        w.Add(New Circle(top + 0.3 * down + radius * up, radius, 1.0, id:="ball"))
        Return w
    End Function

    ''' <summary>A 0.2 m square box of 1 kg dropped from rest with its bottom face h0 metres above the floor.</summary>
    Public Function BoxDrop(Optional dropHeight As Double = 1.0, Optional restitution As Double = 0.5,
                            Optional gravity As Double = 9.81) As World
        Dim w As New World(1.0, dropHeight + 1.2, gravity, restitution)
        w.Add(Rectangle.CreateMovable(New Vector(0.4, dropHeight), 0.2, 0.2, 1.0, Vector.Zero, "box"))
        Return w
    End Function

    ''' <summary>
    ''' A bob of radius 0.1 m and 1 kg on a string of length L (m) from a fixed point, released at rest
    ''' at θ0 (rad) from the vertical; e = 1, nothing else in the box.
    ''' </summary>
    Public Function Pendulum(Optional length As Double = 1.5, Optional angle As Double = Math.PI / 3,
                             Optional gravity As Double = 9.81, Optional kind As LinkKind = LinkKind.String) As World
        Dim w As New World(4.0, 4.0, gravity, 1.0)
        Dim pivot = New Vector(2.0, 3.5)
        Dim bob As New Circle(pivot + New Vector(length * Math.Sin(angle), -length * Math.Cos(angle)), 0.1, 1.0, id:="bob")
        w.Add(bob)
        w.Add(Link.CreateTie(kind, bob, pivot, length, "string"))
        Return w
    End Function

    ''' <summary>
    ''' A mass m (kg) hanging from a fixed point on an undamped spring of stiffness k (N/m) and rest
    ''' length 1 m, released at rest with the spring unstretched: it oscillates about mg/k below.
    ''' </summary>
    Public Function SpringMass(Optional stiffness As Double = 20.0, Optional mass As Double = 0.5,
                               Optional gravity As Double = 9.81) As World
        Dim w As New World(3.0, 4.0, gravity, 1.0)
        Dim anchor = New Vector(1.5, 3.5)
        Dim body As New Circle(anchor - New Vector(0, 1.0), 0.15, mass, id:="mass")
        w.Add(body)
        w.Add(Link.CreateSpring(body, anchor, stiffness, 1.0, 0, "spring"))
        Return w
    End Function

    ''' <summary>The app's opening scene: a few balls, a peg and a table, so something happens at once.</summary>
    Public Function Demo() As World
        Dim w As New World(8.0, 5.0, 9.81, 0.9)
        w.Add(New Circle(New Vector(1.0, 3.0), 0.25, 2.0, New Vector(3.0, 0), "red") With {.Color = "#e53935"})
        w.Add(New Circle(New Vector(2.5, 4.0), 0.2, 1.0, New Vector(-1.0, 1.0), "blue") With {.Color = "#1e88e5"})
        w.Add(New Circle(New Vector(6.5, 3.5), 0.3, 4.0, New Vector(-2.0, 0), "green") With {.Color = "#43a047"})
        w.Add(Circle.CreateFixed(New Vector(4.0, 1.5), 0.3, "peg"))
        w.Add(New Rectangle(New Vector(5.5, 0.0), 2.0, 1.2, "table"))
        Return w
    End Function
End Module
