Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>
''' The time controls in the real window under Xvfb: step, step back, the next collision, the
''' timeline scrubbed with the mouse, their keys, and Tab through the side panel. Each is checked
''' against the numbers the app traces (positions and velocities to the last bit) and photographed.
''' </summary>
<Collection(RealWindow.Name)>
Public Class TimeTravelGuiTests
    ''' <summary>The time and the bodies' states the app traced after its last time-control line matching <paramref name="pattern"/>.</summary>
    Private Shared Function StateAfter(app As AppDriver, pattern As String, from As Integer) As (Time As Double, Collisions As Long, Bodies As Dictionary(Of String, Double()))
        app.WaitFor(pattern, skip:=from)
        Dim at = Array.FindLastIndex(app.Lines(), Function(l) Regex.IsMatch(l, pattern))
        ' The states follow the step's line in the same call, but may reach the trace a moment later: wait for their end.
        Dim count = Integer.Parse(app.WaitFor("^states end, (\d+) bodies$", skip:=at + 1).Groups(1).Value, CultureInfo.InvariantCulture)
        Dim lines = app.Lines()
        Dim head = Regex.Match(lines(at), "t=(\S+) s, collisions (\d+)")
        Dim bodies As New Dictionary(Of String, Double())(StringComparer.Ordinal)
        For i = at + 1 To lines.Length - 1
            If lines(i).StartsWith("states end", StringComparison.Ordinal) Then Exit For
            Dim s = Regex.Match(lines(i), "^state (\S+) (\S+) (\S+) (\S+) (\S+)$")
            If Not s.Success Then Continue For
            bodies(s.Groups(1).Value) = Enumerable.Range(2, 4).Select(Function(g) Double.Parse(s.Groups(g).Value, CultureInfo.InvariantCulture)).ToArray()
        Next
        Assert.Equal(count, bodies.Count)
        Return (Double.Parse(head.Groups(1).Value, CultureInfo.InvariantCulture), Long.Parse(head.Groups(2).Value, CultureInfo.InvariantCulture), bodies)
    End Function

    Private Shared Sub AssertSame(expected As Dictionary(Of String, Double()), actual As Dictionary(Of String, Double()), tolerance As Double, what As String)
        Assert.Equal(expected.Keys.OrderBy(Function(k) k), actual.Keys.OrderBy(Function(k) k))
        For Each kv In expected
            For i = 0 To 3
                Assert.True(Math.Abs(kv.Value(i) - actual(kv.Key)(i)) <= tolerance, $"{what}: body {kv.Key} number {i}: {kv.Value(i)} <> {actual(kv.Key)(i)}")
            Next
        Next
    End Sub

    <GuiFact>
    Public Sub StepStepBackNextCollisionAndTheTimeline_ShowTheRecordedStates()
        Using app As New AppDriver()
            Thread.Sleep(1500) ' the demo runs for a while
            Dim from = app.Mark()
            app.Click("step")
            Dim s1 = StateAfter(app, "^step t=", from)
            Assert.True(s1.Bodies.Count > 0, app.X.AppOutput())
            from = app.Mark()
            app.Click("step")
            app.WaitFor("^step t=", skip:=from)
            from = app.Mark()
            app.Click("step")
            Dim s3 = StateAfter(app, "^step t=", from)
            Assert.InRange(s3.Time - s1.Time, 2 / 60.0 - 2.0E-6, 2 / 60.0 + 2.0E-6)
            app.X.Shoot("time-step")

            ' Two frames back: the state of the first step again.
            from = app.Mark()
            app.Click("step-back")
            app.WaitFor("^step back t=", skip:=from)
            from = app.Mark()
            app.Click("step-back")
            Dim back = StateAfter(app, "^step back t=", from)
            Assert.InRange(back.Time - s1.Time, -2.0E-6, 2.0E-6)
            AssertSame(s1.Bodies, back.Bodies, 1.0E-9, "two frames back")
            app.X.Shoot("time-step-back")

            ' On to the next collision: the count goes up, and the time with it.
            from = app.Mark()
            app.Click("next-collision")
            Dim hit = StateAfter(app, "^next collision ", from)
            Assert.True(hit.Collisions > back.Collisions, "collisions " & back.Collisions & " → " & hit.Collisions)
            Assert.True(hit.Time > back.Time)
            app.X.Shoot("time-next-collision")

            ' The timeline scrubbed with the mouse to its left end: the demo as it was built, at t = 0.
            Dim bar = app.ScrollIntoView("timeline")
            from = app.Mark()
            app.Drag(1, bar.X + bar.W - S(14, bar.H), bar.Y + bar.H \ 3, bar.X + 2, bar.Y + bar.H \ 3)
            Thread.Sleep(500)
            app.WaitFor("^rewound t=0\.000000 s", skip:=from)
            Dim start = StateAfter(app, "^rewound t=0\.000000 s", from)
            Dim demo = Scenarios.Demo()
            Dim expected = demo.Movables.ToDictionary(Function(b) b.Id, Function(b) New Double() {b.Position.X, b.Position.Y, b.Velocity.X, b.Velocity.Y}, StringComparer.Ordinal)
            AssertSame(expected, start.Bodies, 0.0, "the start")
            app.X.Shoot("time-timeline-start")

            ' Scrubbed to its right end: the latest moment reached (the step to the collision looked a little past it).
            from = app.Mark()
            app.Drag(1, bar.X + S(14, bar.H), bar.Y + bar.H \ 3, bar.X + bar.W - 2, bar.Y + bar.H \ 3)
            Thread.Sleep(500)
            Dim latest = StateAfter(app, "^rewound t=", from)
            Dim line = app.Lines().Last(Function(l) l.StartsWith("rewound t=", StringComparison.Ordinal))
            Dim ends = Regex.Match(line, "timeline (\S+) to (\S+) s")
            Assert.InRange(latest.Time - Double.Parse(ends.Groups(2).Value, CultureInfo.InvariantCulture), -2.0E-6, 2.0E-6)
            Assert.True(latest.Time >= hit.Time)
            ' Back collision by collision from there (the step looked a frame past the one it found, and
            ' may have seen another): the collision the step found again, to the last bit.
            Dim again = latest
            For k = 1 To 5
                from = app.Mark()
                app.Click("previous-collision")
                again = StateAfter(app, "^previous collision t=", from)
                If again.Time <= hit.Time + 2.0E-6 Then Exit For
            Next
            Assert.InRange(again.Time - hit.Time, -2.0E-6, 2.0E-6)
            Assert.Equal(hit.Collisions, again.Collisions)
            AssertSame(hit.Bodies, again.Bodies, 0.0, "the collision found again")
            app.X.Shoot("time-previous-collision")
            Assert.True(app.X.AppIsRunning, app.X.AppOutput())
        End Using
    End Sub

    ''' <summary>How far in from a slider's end its thumb's middle is, px (Mono's thumb is about a third as wide as the bar is tall).</summary>
    Private Shared Function S(px As Integer, height As Integer) As Integer
        Return Math.Max(px, height \ 3)
    End Function

    <GuiFact>
    Public Sub Keys_StepAndStepBack_ButATextBoxKeepsItsKeys()
        Using app As New AppDriver()
            Thread.Sleep(800)
            app.Click("pause")
            Thread.Sleep(300)
            Dim from = app.Mark()
            app.X.XDo("key", "period")
            Dim a = StateAfter(app, "^step t=", from)
            from = app.Mark()
            app.X.XDo("key", "period")
            app.WaitFor("^step t=", skip:=from)
            from = app.Mark()
            app.X.XDo("key", "comma")
            Dim b = StateAfter(app, "^step back t=", from)
            AssertSame(a.Bodies, b.Bodies, 1.0E-9, "a frame on and back by keys")
            from = app.Mark()
            app.X.XDo("key", "ctrl+Right")
            app.WaitFor("^key next collision$", skip:=from)
            app.WaitFor("^next collision ", skip:=from)

            ' In a text box . and the arrows are the box's.
            app.Click("radius")
            app.X.XDo("key", "ctrl+a")
            app.X.XDo("key", "BackSpace")
            from = app.Mark()
            app.X.XDo("type", "--delay", "30", "0.35")
            app.X.XDo("key", "Left")
            app.X.XDo("key", "comma")
            Thread.Sleep(400)
            Assert.Equal("0.3,5", app.Inputs()("Radius"))
            Assert.DoesNotContain(app.Lines().Skip(from), Function(l) l.StartsWith("key step", StringComparison.Ordinal))
        End Using
    End Sub

    <GuiFact>
    Public Sub Tab_ReachesEverySidePanelControl_InReadingOrder()
        Using app As New AppDriver()
            app.Click("pause")
            Thread.Sleep(300)
            Dim from = app.Mark()
            Dim seen As New List(Of String)
            For k = 1 To 120
                app.X.XDo("key", "Tab")
                Thread.Sleep(60)
            Next
            Thread.Sleep(500)
            ' Each focus line names the control (or "-"); the panel may scroll on the way, so the order is
            ' checked on the controls' places in the laid-out panel, not where they are on the screen now.
            For Each line In app.Lines().Skip(from)
                Dim m = Regex.Match(line, "^focus -?\d+ -?\d+ \S+ (\S+)$")
                If m.Success AndAlso m.Groups(1).Value <> "-" Then seen.Add(m.Groups(1).Value)
            Next
            ' One round of the side panel: from Pause to the last control, before it comes round again.
            Dim first = seen.IndexOf("pause")
            Assert.True(first >= 0, "Tab never reached Pause" & vbLf & String.Join(vbLf, seen))
            Dim again = seen.IndexOf("pause", first + 1)
            Dim round = seen.Skip(first).Take(If(again > 0, again - first, seen.Count - first)).ToList()
            Dim names = {"pause", "reset", "delete-mode", "speed", "gravity", "moon", "restitution", "radius", "mass", "sides", "angle", "fixed",
                         "add-circle", "add-polygon", "rect-width", "rect-height", "rect-fixed", "add-rectangle", "add-ramp", "stiffness", "add-spring",
                         "add-rod", "add-string", "box-width", "box-height", "resize", "large-fonts", "high-contrast", "arrows", "tutorial", "maths",
                         "open", "save", "timeline", "previous-collision", "step-back", "step", "next-collision"}
            For Each name In names
                Assert.True(round.Contains(name), "Tab never reached " & name & vbLf & String.Join(vbLf, round))
            Next
            ' Reading order: each control is below the last one's row, or on its row to the right.
            For i = 1 To round.Count - 1
                Dim p = app.Control(round(i - 1)), q = app.Control(round(i))
                Assert.True(q.Y > p.Y + 8 OrElse (Math.Abs(q.Y - p.Y) <= 8 AndAlso q.X > p.X), $"Tab went from {round(i - 1)} {p} to {round(i)} {q}")
            Next
        End Using
    End Sub
End Class
