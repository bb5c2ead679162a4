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
    ''' A box pile: <paramref name="count"/> movable boxes of mixed sizes (sides 0.2 to 0.5 m, 10 kg/m²,
    ''' frictionless, never rotating) wait at rest in rows 0.6 m apart with gaps of at least 0.15 m between
    ''' them, the lowest row 0.5 m above the floor of a walled container <paramref name="width"/> m wide,
    ''' and fall into it (g = 9.81, restitution e) until the pile settles. The container is 1 m taller than
    ''' the top row. The same seed gives the same scene.
    ''' </summary>
    Public Function BoxPile(Optional count As Integer = 200, Optional width As Double = 10.0, Optional restitution As Double = 0.3,
                            Optional seed As Integer = 1) As World
        If count < 1 Then Throw New ArgumentOutOfRangeException(NameOf(count))
        Const margin = 0.3        ' m from the side walls to the first box of a row
        Const gap = 0.15          ' m between neighbours in a row
        Const rowPitch = 0.6      ' m between rows: more than the tallest box, so no two rows touch
        Const density = 10.0      ' kg/m²
        Const smallest = 0.2, largest = 0.5 ' m, a side
        If width < 2 * margin + largest Then Throw New ArgumentOutOfRangeException(NameOf(width), "the container must hold at least one box per row")
        Dim rng As New Random(seed)
        Dim boxes As New List(Of Rectangle)
        Dim x = margin
        Dim y = 0.5
        Dim top = 0.0
        For i = 0 To count - 1
            Dim w = smallest + (largest - smallest) * rng.NextDouble()
            Dim h = smallest + (largest - smallest) * rng.NextDouble()
            If x + w > width - margin Then
                ' A new row, started a little way in so that rows do not line up edge over edge.
                x = margin + 0.1 * rng.NextDouble()
                y += rowPitch
            End If
            boxes.Add(Rectangle.CreateMovable(New Vector(x, y), w, h, density * w * h, Vector.Zero, "box" & i.ToString(Globalization.CultureInfo.InvariantCulture)))
            top = Math.Max(top, y + h)
            x += w + gap
        Next
        Dim world As New World(width, top + 1.0, 9.81, restitution)
        For Each b In boxes
            world.Add(b)
        Next
        Return world
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

    ''' <summary>
    ''' A Galton board: <paramref name="balls"/> balls (radius 12.5 mm, 10 g) wait in rows on shelves
    ''' that slope 0.25° towards the middle, two columns of them one above another. All slide at the
    ''' same g sin θ, so they never touch, and drop off each shelf's end one after another into a funnel
    ''' and a chute above <paramref name="rows"/> staggered rows of fixed pegs (radius 10 mm, 87.5 mm
    ''' apart) between two side walls <paramref name="columns"/> peg spacings apart, with a bin under
    ''' each gap of the last row. e = 0.5. Each row sends a ball half a spacing left or right, so the
    ''' bins fill to a binomial (bell) shape.
    ''' </summary>
    Public Function GaltonBoard(Optional balls As Integer = 240, Optional rows As Integer = 12, Optional columns As Integer = 20,
                                Optional shelves As Integer = 8) As World
        If balls < 1 Then Throw New ArgumentOutOfRangeException(NameOf(balls))
        If rows < 1 Then Throw New ArgumentOutOfRangeException(NameOf(rows))
        If columns < 2 Then Throw New ArgumentOutOfRangeException(NameOf(columns))
        If shelves < 2 OrElse shelves Mod 2 <> 0 Then Throw New ArgumentOutOfRangeException(NameOf(shelves), "an even number of shelves, 2 or more")
        Const r = 0.0125, pegRadius = 0.01, spacing = 0.0875, mass = 0.01
        Const ballGap = 2.6 * r           ' centre to centre along a shelf, m
        Const binTop = 0.375, chuteHalf = 0.0625, levelGap = 0.2
        Const Wall = "#546e7a"
        Dim slope = 0.25 * Math.PI / 180
        Dim rowGap = spacing * 0.866
        Dim perShelf = (balls + shelves - 1) \ shelves
        Dim shelfLength = perShelf * ballGap + 0.125
        Dim levels = shelves \ 2
        Dim boardWidth = columns * spacing
        Dim width = Math.Max(boardWidth, 2 * (shelfLength * Math.Cos(slope) + 0.0375 + 0.05 * (levels - 1)) + 0.125)
        Dim cx = width / 2
        Dim left = cx - boardWidth / 2, right = cx + boardWidth / 2
        Dim lastRow = binTop + 0.5 * rowGap + 0.0375
        Dim topRow = lastRow + (rows - 1) * rowGap
        Dim chuteBottom = topRow + 0.0625, chuteTop = chuteBottom + 0.3125
        Dim funnelTop = chuteTop + 0.375
        Dim top = funnelTop
        Dim shelfEnds As New List(Of (Start As Vector, Finish As Vector, Side As Integer))
        For s = 0 To shelves - 1
            Dim side = If(s Mod 2 = 0, -1, 1)
            Dim level = s \ 2
            Dim yEnd = funnelTop + 0.0625 + level * levelGap + If(side > 0, 0.0375, 0)
            Dim xEnd = cx + side * (0.0375 + 0.05 * (levels - 1 - level))
            Dim start = New Vector(xEnd + side * shelfLength * Math.Cos(slope), yEnd + shelfLength * Math.Sin(slope))
            shelfEnds.Add((start, New Vector(xEnd, yEnd), side))
            top = Math.Max(top, start.Y + 0.0625)
        Next
        Dim w As New World(width, top + 0.0625, 9.81, 0.5)
        w.Add(New Segment(New Vector(left, 0), New Vector(left, chuteTop), "side-left") With {.Color = Wall})
        w.Add(New Segment(New Vector(right, 0), New Vector(right, chuteTop), "side-right") With {.Color = Wall})
        Dim x = cx - spacing / 2
        While x > left + spacing
            x -= spacing
        End While
        Dim bin = 0
        While x < right - r
            bin += 1
            w.Add(New Rectangle(New Vector(x - 0.005, 0), 0.01, binTop, "bin" & bin) With {.Color = "#78909c"})
            x += spacing
        End While
        Dim peg = 0
        For k = 0 To rows - 1
            Dim y = lastRow + (rows - 1 - k) * rowGap
            Dim offset = If(k Mod 2 = 0, 0.0, spacing / 2)
            For j = -columns To columns
                Dim px = cx + offset + j * spacing
                If px < left + pegRadius + 0.01875 OrElse px > right - pegRadius - 0.01875 Then Continue For
                peg += 1
                Dim pin = Circle.CreateFixed(New Vector(px, y), pegRadius, "peg" & peg)
                pin.Color = "#455a64"
                w.Add(pin)
            Next
        Next
        w.Add(New Segment(New Vector(cx - chuteHalf, chuteBottom), New Vector(cx - chuteHalf, chuteTop), "chute-left") With {.Color = Wall})
        w.Add(New Segment(New Vector(cx + chuteHalf, chuteBottom), New Vector(cx + chuteHalf, chuteTop), "chute-right") With {.Color = Wall})
        w.Add(New Segment(New Vector(cx - 0.5, funnelTop), New Vector(cx - chuteHalf, chuteTop), "funnel-left") With {.Color = Wall})
        w.Add(New Segment(New Vector(cx + chuteHalf, chuteTop), New Vector(cx + 0.5, funnelTop), "funnel-right") With {.Color = Wall})
        Dim colours = {"#e53935", "#1e88e5", "#43a047", "#fb8c00", "#8e24aa"}
        Dim placed = 0
        For s = 0 To shelves - 1
            Dim shelf = shelfEnds(s)
            w.Add(New Segment(shelf.Start, shelf.Finish, "shelf" & (s + 1)) With {.Color = Wall})
            Dim down = New Vector(-shelf.Side * Math.Cos(slope), -Math.Sin(slope))
            Dim up = New Vector(-down.Y, down.X)
            If up.Y < 0 Then up = -1 * up
            For k = 0 To perShelf - 1
                If placed = balls Then Exit For
                placed += 1
                ' Touching the shelf to within a nanometre: it settles onto it at once and slides.
                Dim p = shelf.Finish - (0.075 + k * ballGap) * down + (r + 0.000000001) * up
                w.Add(New Circle(p, r, mass, id:="b" & placed) With {.Color = colours(placed Mod colours.Length)})
            Next
        Next
        Return w
    End Function

    ''' <summary>
    ''' A projectile in air with linear drag b (N·s/m): a ball of mass m launched from (1, 1) m at v0 (m/s) and θ (rad),
    ''' in a walled box 20 m × 10 m. It follows x(t) = x0 + v_t t + (v0 − v_t) τ (1 − e^(−t/τ)), τ = m/b (docs/forces.md).
    ''' </summary>
    Public Function DragProjectile(Optional speed As Double = 10.0, Optional angle As Double = Math.PI / 4, Optional linearDrag As Double = 0.2,
                                   Optional mass As Double = 0.5, Optional gravity As Double = 9.81) As World
        Dim w As New World(20.0, 10.0, gravity, 1.0)
        Dim v = New Vector(speed * Math.Cos(angle), speed * Math.Sin(angle))
        w.Add(New Circle(New Vector(1.0, 1.0), 0.05, mass, v, "ball") With {.LinearDrag = linearDrag})
        Return w
    End Function

    ''' <summary>
    ''' A ball of mass m (kg) and radius r (m) dropped from rest 95 m up in air of density ρ (kg/m²) with drag coefficient
    ''' C_d: it falls at v(t) = v_t tanh(g t/v_t), v_t = √(2 m g/(ρ C_d 2r)).
    ''' </summary>
    Public Function AirFall(Optional mass As Double = 0.2, Optional radius As Double = 0.15, Optional airDensity As Double = 1.2,
                            Optional dragCoefficient As Double = 0.8, Optional gravity As Double = 9.81) As World
        Dim w As New World(10.0, 100.0, gravity, 1.0) With {.AirDensity = airDensity}
        w.Add(New Circle(New Vector(5.0, 95.0), radius, mass, id:="ball") With {.DragCoefficient = dragCoefficient})
        Return w
    End Function

    ''' <summary>
    ''' A box (mass m, width w, 0.5 m tall) in a tank of water (density ρ_l, kg/m², surface 1.5 m up, as wide as the
    ''' container), released at rest <paramref name="displacement"/> m above its floating depth m/(ρ_l w): undamped, it
    ''' bobs about that depth with period 2π √(m/(ρ_l g w)).
    ''' </summary>
    Public Function FloatingBox(Optional mass As Double = 40.0, Optional width As Double = 0.4, Optional liquidDensity As Double = 1000.0,
                                Optional displacement As Double = 0.03, Optional gravity As Double = 9.81) As World
        Dim w As New World(4.0, 3.0, gravity, 0.5)
        w.Add(New Liquid(New Vector(0, 0), 4.0, 1.5, liquidDensity, "water") With {.Color = "#1e88e5"})
        Dim depth = Buoyancy.FloatingDepth(mass, width, liquidDensity)
        w.Add(Rectangle.CreateMovable(New Vector(2.0 - width / 2, 1.5 - depth + displacement), width, 0.5, mass, id:="box"))
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
