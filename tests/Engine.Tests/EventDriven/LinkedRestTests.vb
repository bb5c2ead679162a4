Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Bodies coming to rest, and sliding, on supports other than the floor in scenes with links, in the event
    ''' solver, against closed forms: a box on a slack string bouncing on a fixed table (eⁿv₀, the series' sum
    ''' t₀(1 + e)/(1 − e)), a ball on the table, a box on a vertical spring on a shelf (still, and dropped), a box
    ''' sliding down a ramp (s = ½ g sin θ t², leaving its end on the parabola), a box settling in a V, a box
    ''' bouncing to rest on a box on the floor, and a box left behind in the air when the one beneath is knocked
    ''' away; the Verlet solver agreeing at O(dt) on the ramp. Boxes are 0.25 m square so that every position is
    ''' exact in binary.
    ''' </summary>
    Public Class LinkedRestTests
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        ''' <summary>The time of the n-th bounce (n ≥ 1) of a body dropped from rest t₀ before the first: each flight after bounce k is 2eᵏv₀/g.</summary>
        Private Shared Function BounceTime(n As Integer, t0 As Double, v0 As Double, e As Double) As Double
            Dim t = t0
            For k = 1 To n - 1
                t += 2 * Math.Pow(e, k) * v0 / G
            Next
            Return t
        End Function

        ' ---- A fixed table ----

        <Fact>
        Public Sub BoxOnASlackString_DroppedOntoAFixedTable_ReboundsAtEToTheN_RestsAtTheSeriesSum_NeverBelowTheTop()
            Const E As Double = 0.5, H0 As Double = 0.5
            Dim w = NewWorld("event", E)
            Dim table As New Rectangle(New Vector(1, 0), 2, 1, "table")
            w.Add(table)
            Dim box = Rectangle.CreateMovable(New Vector(1.875, 1 + H0), 0.25, 0.25, 1, Vector.Zero, "box")
            w.Add(box)
            ' Slack all the way: its centre 2.375 m from the anchor at the start, 2.875 m at rest, of 3.5 m.
            Dim tie = Link.CreateTie(LinkKind.String, box, New Vector(2, 4), 3.5)
            w.Add(tie)
            Dim bounces As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.A Is box AndAlso r.B Is table Then bounces.Add(r)
            Dim t0 = Math.Sqrt(2 * H0 / G), v0 = Math.Sqrt(2 * G * H0)
            Dim restTime = t0 * (1 + E) / (1 - E)
            Dim lowest = Double.PositiveInfinity
            Do While w.Time < restTime + 0.5
                w.Advance(0.001)
                lowest = Math.Min(lowest, box.Position.Y)
            Loop
            _output.WriteLine($"{bounces.Count} bounces, the last at {bounces.Last().Time} s of {restTime} s; lowest {lowest} m; at {box.Position} with {box.Velocity}")
            Assert.True(bounces.Count >= 10)
            For n = 1 To 10
                Assert.Equal(BounceTime(n, t0, v0, E), bounces(n - 1).Time, 9)
                Assert.Equal(Math.Pow(E, n) * v0, bounces(n - 1).AVelocityAfter.Y, 9)
                Assert.Equal(0.0, bounces(n - 1).AVelocityAfter.X)
            Next
            Assert.True(bounces.Last().Time <= restTime AndAlso restTime - bounces.Last().Time < 0.001, $"the last bounce at {bounces.Last().Time} s, the series ends at {restTime} s")
            Assert.True(lowest >= 1.0, $"{lowest} m: below the table's top")
            Assert.Equal(New Vector(1.875, 1.0), box.Position)
            Assert.Equal(Vector.Zero, box.Velocity)
            Dim count = bounces.Count
            w.Advance(1)
            Assert.Equal(count, bounces.Count)
            Assert.Equal(New Vector(1.875, 1.0), box.Position)
            Assert.Equal(0.0, tie.Tension)
        End Sub

        <Fact>
        Public Sub ABallDroppedOntoAFixedTable_InASceneWithLinks_ComesToRestOnItsTop_InFewEvents()
            Const E As Double = 0.5
            Dim w = NewWorld("event", E)
            AddFarPendulum(w)
            w.Add(New Rectangle(New Vector(1, 0), 2, 1, "table"))
            Dim ball As New Circle(New Vector(1.5, 1.5), 0.125, 1, Vector.Zero, "ball")
            w.Add(ball)
            Dim hits = 0
            w.CollisionListener = Sub(r) If r.A Is ball Then hits += 1
            Dim lowest = Double.PositiveInfinity
            Do While w.Time < 3
                w.Advance(0.001)
                lowest = Math.Min(lowest, ball.Position.Y)
            Loop
            _output.WriteLine($"{hits} bounces; lowest {lowest} m; at {ball.Position} with {ball.Velocity}")
            ' Without the rest rule it chattered on (tens of thousands of events) and sank into the table.
            Assert.InRange(hits, 10, 40)
            Assert.True(lowest >= 1.125, $"{lowest} m: below the table's top")
            Assert.Equal(New Vector(1.5, 1.125), ball.Position)
            Assert.Equal(Vector.Zero, ball.Velocity)
        End Sub

        ' ---- Other level faces, other shapes ----

        <Theory>
        <InlineData("box on a level segment")>
        <InlineData("ball on a level segment")>
        <InlineData("triangle on a fixed polygon's top")>
        <InlineData("box on a fixed triangle's level top")>
        Public Sub ABodyDroppedOnALevelFace_ComesToRestOnIt_NeverBelowIt(scene As String)
            Dim w = NewWorld("event", 0.5)
            AddFarPendulum(w)
            Dim body As Shape
            Select Case scene
                Case "box on a level segment"
                    w.Add(New Segment(New Vector(1, 1), New Vector(3, 1), "shelf"))
                    body = Rectangle.CreateMovable(New Vector(1.875, 1.5), 0.25, 0.25, 1, Vector.Zero, "body")
                Case "ball on a level segment"
                    w.Add(New Segment(New Vector(1, 1), New Vector(3, 1), "shelf"))
                    body = New Circle(New Vector(2, 1.5), 0.125, 1, Vector.Zero, "body")
                Case "triangle on a fixed polygon's top"
                    w.Add(Polygon.CreateFixed({New Vector(1, 0), New Vector(3, 0), New Vector(2.75, 1), New Vector(1.25, 1)}, "trapezium"))
                    body = New Polygon({New Vector(1.75, 1.5), New Vector(2.25, 1.5), New Vector(2, 1.75)}, 1, Vector.Zero, "body")
                Case Else
                    ' A triangle standing on its point: its level top is a face at y = 1.
                    w.Add(Polygon.CreateFixed({New Vector(2, 0), New Vector(3, 1), New Vector(1, 1)}, "wedge"))
                    body = Rectangle.CreateMovable(New Vector(1.875, 1.5), 0.25, 0.25, 1, Vector.Zero, "body")
            End Select
            w.Add(body)
            Dim hits = 0
            w.CollisionListener = Sub(r) If r.A Is body OrElse r.B Is body Then hits += 1
            Dim lowest = Double.PositiveInfinity
            Do While w.Time < 3
                w.Advance(0.001)
                lowest = Math.Min(lowest, body.Position.Y + body.Outline.MinY)
            Loop
            Dim bottom = body.Position.Y + body.Outline.MinY
            _output.WriteLine($"{scene}: {hits} bounces; its lowest point at {bottom} m, never below {lowest} m; moving at {body.Velocity}")
            Assert.InRange(hits, 10, 40)
            Assert.Equal(1.0, bottom, 12)
            Assert.True(lowest >= 1 - 0.000000000001, $"{lowest} m: below the face")
            Assert.Equal(Vector.Zero, body.Velocity)
        End Sub

        <Fact>
        Public Sub ABoxSlidingAlongATable_LeavesItsEdge_AndLandsAtTheFreeFallTime()
            Dim w = NewWorld("event", 0.5)
            AddFarPendulum(w)
            Dim table As New Rectangle(New Vector(1, 0), 2, 1, "table")
            w.Add(table)
            Dim box = Rectangle.CreateMovable(New Vector(2, 1), 0.25, 0.25, 1, New Vector(1, 0), "box")
            w.Add(box)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.A Is box Then records.Add(r)
            w.Advance(0.5)
            Assert.Equal(New Vector(2.5, 1), box.Position)
            Assert.Equal(New Vector(1, 0), box.Velocity)
            ' Its left end passes the table's edge at x = 3 after 1 s; then it falls 1 m, sliding on at 1 m/s.
            w.Advance(1.5)
            Dim fall = Math.Sqrt(2 / G)
            Dim landing = records.First()
            Assert.Equal(WallSide.Bottom, landing.Wall)
            Assert.Equal(1 + fall, landing.Time, 9)
            Assert.Equal(1.0, landing.AVelocityBefore.X)
            Assert.Equal(-G * fall, landing.AVelocityBefore.Y, 9)
            Assert.Equal(3 + fall, box.Position.X - (w.Time - landing.Time), 9)
        End Sub

        ' ---- A vertical spring over a shelf ----

        Private Shared Function SpringOverShelf(restLength As Double, boxBottom As Double, ByRef box As Rectangle, ByRef spring As Link) As World
            Dim w = NewWorld("event", 0.5)
            w.Add(New Rectangle(New Vector(4, 0), 2, 2, "shelf"))
            box = Rectangle.CreateMovable(New Vector(4.875, boxBottom), 0.25, 0.25, 0.5, Vector.Zero, "box")
            w.Add(box)
            spring = Link.CreateSpring(box, New Vector(5, 4), 20, restLength)
            w.Add(spring)
            Return w
        End Function

        <Fact>
        Public Sub BoxOnASpringPullingLessThanItsWeight_RestsStillOnAShelf_AndOnePullingMoreLiftsOffAsTheCosine()
            ' Rest length 1.8 m, 1.875 m to the anchor: the spring pulls 20 × 0.075 = 1.5 N of the weight's 4.905 N.
            Dim box As Rectangle = Nothing, spring As Link = Nothing
            Dim w = SpringOverShelf(1.8, 2, box, spring)
            Dim hits = 0
            w.CollisionListener = Sub(r) hits += 1
            w.Advance(2)
            Assert.Equal(New Vector(4.875, 2.0), box.Position)
            Assert.Equal(Vector.Zero, box.Velocity)
            Assert.Equal(0, hits)
            Assert.Equal(1.5, spring.Tension, 12)
            ' Rest length 1.5 m: it pulls 7.5 N, more than the weight, and the box rises about y_eq = 4 − L − mg/k.
            w = SpringOverShelf(1.5, 2, box, spring)
            Dim yEq = 4 - 1.5 - 0.5 * G / 20 - 0.125, omega = Math.Sqrt(20 / 0.5)
            w.Advance(0.1)
            Assert.Equal(yEq + (2 - yEq) * Math.Cos(omega * 0.1), box.Position.Y, 9)
        End Sub

        <Fact>
        Public Sub BoxOnASpringDroppedOntoAShelf_ReboundsAtEToTheN_ComesToRestStill_NeverBelowTheTop()
            Const E As Double = 0.5, K As Double = 20, M As Double = 0.5
            Dim box As Rectangle = Nothing, spring As Link = Nothing
            ' Released 0.3 m above the shelf, its centre 1.575 m from the anchor (compressed by 0.225 m); it lands 1.875 m from it.
            Dim w = SpringOverShelf(1.8, 2.3, box, spring)
            Dim bounces As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.A Is box Then bounces.Add(r)
            ' Energy: ½mv₁² = mg × 0.3 − ½k(0.075² − 0.225²); each flight on the spring gives back the speed it left with.
            Dim v1 = Math.Sqrt(2 * (M * G * 0.3 - 0.5 * K * (0.075 * 0.075 - 0.225 * 0.225)) / M)
            Dim lowest = Double.PositiveInfinity
            Do While w.Time < 3
                w.Advance(0.001)
                lowest = Math.Min(lowest, box.Position.Y)
            Loop
            _output.WriteLine($"{bounces.Count} bounces, the last at {bounces.Last().Time} s; lowest {lowest} m; at {box.Position} with {box.Velocity}")
            Assert.True(bounces.Count >= 8)
            Assert.Equal(-v1, bounces(0).AVelocityBefore.Y, 9)
            For n = 1 To 8
                Assert.Equal(Math.Pow(E, n) * v1, bounces(n - 1).AVelocityAfter.Y, 9)
            Next
            Assert.True(lowest >= 2.0, $"{lowest} m: below the shelf")
            Assert.Equal(New Vector(4.875, 2.0), box.Position)
            Assert.Equal(Vector.Zero, box.Velocity)
            Dim count = bounces.Count
            w.Advance(1)
            Assert.Equal(count, bounces.Count)
        End Sub

        ' ---- A ramp ----

        Private Const Theta As Double = Math.PI / 6

        ''' <summary>
        ''' A fixed ramp whose slope falls from (1, 2 + 3 tan θ) to (4, 2), in the air; a body touching it
        ''' <paramref name="along"/> m down the slope: a box or a triangle by its lower-left corner, a ball by its rim.
        ''' </summary>
        Private Shared Function Ramp(solver As String, along As Double, ByRef body As Shape, ByRef top As Vector, Optional dt As Double = 0.001, Optional shape As String = "box") As World
            Dim w = NewWorld(solver, 0.5, dt)
            AddFarPendulum(w)
            top = New Vector(1, 2 + 3 * Math.Tan(Theta))
            w.Add(Polygon.CreateFixed({New Vector(1, 2), New Vector(4, 2), top}, "ramp"))
            Dim p = top + New Vector(Math.Cos(Theta), -Math.Sin(Theta)) * along
            Select Case shape
                Case "ball"
                    body = New Circle(p + New Vector(Math.Sin(Theta), Math.Cos(Theta)) * 0.125, 0.125, 1, Vector.Zero, "body")
                Case "triangle"
                    body = New Polygon({p, p + New Vector(0.25, 0), p + New Vector(0.125, 0.25)}, 1, Vector.Zero, "body")
                Case Else
                    body = Rectangle.CreateMovable(p, 0.25, 0.25, 1, Vector.Zero, "body")
            End Select
            w.Add(body)
            Return w
        End Function

        <Theory>
        <InlineData("box")>
        <InlineData("ball")>
        <InlineData("triangle")>
        Public Sub ABodyReleasedOnARamp_InASceneWithLinks_SlidesWithHalfGSinThetaTSquared_AndLeavesItsEndOnTheParabola(shape As String)
            Dim box As Shape = Nothing, top As Vector
            Dim w = Ramp("event", 0.5, box, top, shape:=shape)
            Dim down As New Vector(Math.Cos(Theta), -Math.Sin(Theta))
            Dim start = box.Position
            Dim hits = 0
            w.CollisionListener = Sub(r) If r.A Is box Then hits += 1
            Dim energy0 = G * start.Y
            For Each t In {0.25, 0.5, 0.75}
                w.Advance(t - w.Time)
                Dim s = 0.5 * G * Math.Sin(Theta) * t * t
                Dim expected = start + down * s
                _output.WriteLine($"t = {t} s: {box.Position}, expected {expected}, off by {(box.Position - expected).Length} m")
                Assert.True((box.Position - expected).Length < 0.000000001, $"at {t} s: {box.Position}, expected {expected}")
                Assert.True((box.Velocity - down * (G * Math.Sin(Theta) * t)).Length < 0.000000001)
                ' Energy per kg, ½v² + g y, is what it started with.
                Assert.Equal(energy0, 0.5 * box.Velocity.LengthSquared + G * box.Position.Y, 9)
            Next
            ' It reaches the end, 3/cos θ − 0.5 m on, with v² = 2 g sin θ × that, and flies from there.
            Dim rest = 3 / Math.Cos(Theta) - 0.5
            Dim tEnd = Math.Sqrt(2 * rest / (G * Math.Sin(Theta)))
            Dim vEnd = down * (G * Math.Sin(Theta) * tEnd)
            ' Its reference point as it leaves: the box's corner at the ramp's end; a ball's centre or a
            ' triangle's centroid as far from that end as it started from where it touched.
            Dim pEnd = New Vector(4, 2) + (start - (top + down * 0.5))
            w.Advance(tEnd + 0.1 - w.Time)
            Dim flown = pEnd + vEnd * 0.1 + New Vector(0, -0.5 * G * 0.01)
            _output.WriteLine($"off the end at {tEnd} s; at {tEnd + 0.1} s {box.Position}, expected {flown}")
            Assert.True((box.Position - flown).Length < 0.000000001, $"{box.Position}, expected {flown}")
            Assert.Equal(0, hits)
        End Sub

        <Fact>
        Public Sub BoxReleasedOnARamp_Verlet_AgreesAtOrderDt_AfterLeavingItsEnd()
            ' On the slope the acceleration is constant, which Verlet follows exactly; leaving the end it can only
            ' notice at a step, which costs O(dt). So compare 0.1 s after the end (about 1.1 s).
            Const T As Double = 1.2
            Dim box As Shape = Nothing, top As Vector
            Dim w = Ramp("event", 0.5, box, top)
            w.Advance(T)
            Dim exact = box.Position
            Dim errors As New List(Of Double)
            For Each dt In {0.001, 0.0005, 0.00025}
                w = Ramp("verlet", 0.5, box, top, dt)
                w.Advance(T)
                errors.Add((box.Position - exact).Length)
            Next
            _output.WriteLine($"Verlet off by {errors(0)} m at 1 ms, {errors(1)} m at 0.5 ms, {errors(2)} m at 0.25 ms")
            ' Missing the end by up to a step leaves the face's push g cos θ on (or off) for up to dt too long: a
            ' velocity off by at most g cos θ dt, carried for the 0.1 s (and a step) since.
            Dim steps = {0.001, 0.0005, 0.00025}
            For k = 0 To 2
                Dim bound = G * Math.Cos(Theta) * steps(k) * (0.1 + steps(k))
                Assert.True(errors(k) <= bound, $"{errors(k)} m at dt = {steps(k)} s, more than the O(dt) bound {bound} m")
            Next
        End Sub

        ' ---- A V ----

        <Theory>
        <InlineData(4.875)>
        <InlineData(4.8)>
        Public Sub BoxDroppedIntoAV_ComesToRestStillWhereItTouchesBothSlopes(x As Double)
            Dim w = NewWorld("event", 0.5)
            AddFarPendulum(w)
            Dim rise = 3 * Math.Tan(Theta)
            w.Add(Polygon.CreateFixed({New Vector(2, 2), New Vector(5, 2), New Vector(2, 2 + rise)}, "left"))
            w.Add(Polygon.CreateFixed({New Vector(5, 2), New Vector(8, 2), New Vector(8, 2 + rise)}, "right"))
            Dim box = Rectangle.CreateMovable(New Vector(x, 3), 0.25, 0.25, 1, Vector.Zero, "box")
            w.Add(box)
            Dim hits = 0
            w.CollisionListener = Sub(r) If r.A Is box Then hits += 1
            ' Its lower corners on the two slopes, 0.125 m either side of the bottom: 0.125 tan θ up.
            Dim bottom As New Vector(4.875, 2 + 0.125 * Math.Tan(Theta))
            Dim deepest = 0.0
            Do While w.Time < 4
                w.Advance(0.001)
                ' How far the lower corners are below the slopes (n·corner − level, each slope's normal).
                Dim p = box.Position
                Dim intoLeft = -((p.X - 5) * Math.Sin(Theta) + (p.Y - 2) * Math.Cos(Theta))
                Dim intoRight = -(-(p.X + 0.25 - 5) * Math.Sin(Theta) + (p.Y - 2) * Math.Cos(Theta))
                deepest = Math.Max(deepest, Math.Max(intoLeft, intoRight))
            Loop
            _output.WriteLine($"{hits} contacts; at {box.Position} with {box.Velocity}, the bottom at {bottom}; deepest {deepest} m")
            Assert.True((box.Position - bottom).Length < 0.000000000001, $"{box.Position}, expected {bottom}")
            Assert.Equal(Vector.Zero, box.Velocity)
            Assert.True(deepest < 0.000000002, $"{deepest} m into a slope")
            Dim count = hits
            w.Advance(1)
            Assert.Equal(count, hits)
        End Sub

        ' ---- A box on a box ----

        <Fact>
        Public Sub BoxDroppedOnABoxOnTheFloor_ReboundsAtEToTheN_TheFloorTakingTheBlows_AndRestsOnItsTop()
            Const E As Double = 0.5, H0 As Double = 0.5
            Dim w = NewWorld("event", E)
            AddFarPendulum(w)
            Dim lower = Rectangle.CreateMovable(New Vector(4, 0), 0.5, 0.25, 2, Vector.Zero, "lower")
            w.Add(lower)
            Dim upper = Rectangle.CreateMovable(New Vector(4.125, 0.25 + H0), 0.25, 0.25, 1, Vector.Zero, "upper")
            w.Add(upper)
            Dim bounces As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If (r.A Is upper AndAlso r.B Is lower) OrElse (r.A Is lower AndAlso r.B Is upper) Then bounces.Add(r)
            Dim t0 = Math.Sqrt(2 * H0 / G), v0 = Math.Sqrt(2 * G * H0)
            Dim restTime = t0 * (1 + E) / (1 - E)
            Dim lowest = Double.PositiveInfinity
            Do While w.Time < restTime + 0.5
                w.Advance(0.001)
                lowest = Math.Min(lowest, upper.Position.Y)
                Assert.Equal(New Vector(4, 0), lower.Position)
            Loop
            _output.WriteLine($"{bounces.Count} bounces, the last at {bounces.Last().Time} s of {restTime} s; lowest {lowest} m; at {upper.Position}")
            Assert.True(bounces.Count >= 10)
            For n = 1 To 10
                Dim r = bounces(n - 1)
                Dim after = If(r.A Is upper, r.AVelocityAfter, r.BVelocityAfter)
                Dim lowerAfter = If(r.A Is lower, r.AVelocityAfter, r.BVelocityAfter)
                Assert.Equal(BounceTime(n, t0, v0, E), r.Time, 9)
                Assert.Equal(Math.Pow(E, n) * v0, after.Y, 9)
                Assert.True(lowerAfter.Length < 0.000000000001 * v0, $"the lower box moved at {lowerAfter}")
            Next
            Assert.True(bounces.Last().Time <= restTime AndAlso restTime - bounces.Last().Time < 0.001)
            Assert.True(lowest >= 0.25, $"{lowest} m: into the lower box")
            Assert.Equal(New Vector(4.125, 0.25), upper.Position)
            Assert.Equal(Vector.Zero, upper.Velocity)
        End Sub

        <Fact>
        Public Sub ThreeBoxesDroppedOneAboveAnother_SettleIntoAStack_FaceOnFace_NeverOverlapping()
            ' Falling together they touch and part without pressing (free fall presses nothing); landing, the
            ' floor takes each blow through the boxes resting on the one it strikes; the stack comes to rest.
            Dim w = NewWorld("event", 0.3)
            AddFarPendulum(w)
            Dim boxes = {Rectangle.CreateMovable(New Vector(4, 0.5), 0.5, 0.25, 1, Vector.Zero, "bottom"),
                         Rectangle.CreateMovable(New Vector(4.0625, 1.25), 0.5, 0.25, 2, Vector.Zero, "middle"),
                         Rectangle.CreateMovable(New Vector(4.125, 2), 0.5, 0.25, 1, Vector.Zero, "top")}
            For Each b In boxes
                w.Add(b)
            Next
            Dim worst = Double.PositiveInfinity
            Do While w.Time < 5
                w.Advance(0.001)
                worst = Math.Min(worst, Math.Min(boxes(0).Position.Y, Math.Min(boxes(1).Position.Y - boxes(0).Position.Y - 0.25, boxes(2).Position.Y - boxes(1).Position.Y - 0.25)))
            Loop
            _output.WriteLine($"the stack: {String.Join(", ", boxes.Select(Function(b) b.Position.ToString()))}; the least gap {worst} m")
            Assert.True(worst >= -0.000000000001, $"{worst} m: overlapping")
            For k = 0 To 2
                Assert.Equal(0.25 * k, boxes(k).Position.Y, 12)
                Assert.Equal(4 + 0.0625 * k, boxes(k).Position.X)
                Assert.Equal(Vector.Zero, boxes(k).Velocity)
            Next
        End Sub

        <Fact>
        Public Sub BoxResting_OnABoxKnockedAway_StaysWhereItWas_ThenFallsFromItsEdge_AtTheFreeFallTime()
            Const E As Double = 0.5
            Dim w = NewWorld("event", E)
            AddFarPendulum(w)
            Dim lower = Rectangle.CreateMovable(New Vector(4, 0), 0.5, 0.25, 2, Vector.Zero, "lower")
            w.Add(lower)
            Dim upper = Rectangle.CreateMovable(New Vector(4.125, 0.25), 0.25, 0.25, 1, Vector.Zero, "upper")
            w.Add(upper)
            ' A ball rolling along the floor at 2 m/s, 0.5 m from the lower box's face.
            Dim ball As New Circle(New Vector(3.375, 0.125), 0.125, 0.5, New Vector(2, 0), "ball")
            w.Add(ball)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) records.Add(r)
            w.Advance(3)
            Dim blow = records.First()
            Assert.Equal(0.25, blow.Time, 12)
            ' The 1D collision, e = 0.5: the box leaves at (1 + e) m v/(m + M) = 0.6 m/s; momentum kept.
            Dim lowerAfter = If(blow.A Is lower, blow.AVelocityAfter, blow.BVelocityAfter)
            Dim ballAfter = If(blow.A Is ball, blow.AVelocityAfter, blow.BVelocityAfter)
            Assert.Equal(0.6, lowerAfter.X, 12)
            Assert.Equal(1.0, 0.5 * ballAfter.X + 2 * lowerAfter.X, 12)
            ' Frictionless: the upper box stays at x = 4.125 until the lower one's left end passes its right end
            ' (0.375 m at 0.6 m/s), then falls 0.25 m to the floor.
            Dim leaves = 0.25 + 0.375 / 0.6
            Dim landing = records.First(Function(r) r.A Is upper AndAlso r.Wall = WallSide.Bottom)
            Assert.Equal(leaves + Math.Sqrt(2 * 0.25 / G), landing.Time, 9)
            Assert.Equal(0.0, landing.AVelocityBefore.X)
            Assert.Equal(New Vector(4.125, 0.0), upper.Position)
            Assert.Equal(Vector.Zero, upper.Velocity)
        End Sub
    End Class
End Namespace
