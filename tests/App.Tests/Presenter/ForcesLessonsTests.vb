Option Strict On
Imports System.Globalization
Imports System.IO
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The air and liquid lessons of the Scenes menu ("Forces"), opened in the app (event solver) and checked against what their captions claim.</summary>
Public Class ForcesLessonsTests
    Private Const G As Double = 9.81

    Private Shared Function Open(fileName As String) As (H As PresenterHarness, Lesson As Lesson)
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.LessonFolder = Path.Combine(ProcessRunner.RepoRoot, "scenes")
        Dim lesson = h.P.Lessons().Single(Function(l) l.FileName = fileName)
        Assert.Equal("Forces", LessonTopics.TopicOf(fileName))
        h.P.OpenLesson(lesson)
        Assert.Equal(lesson.Title & ": " & lesson.Summary, h.View.LastMessage)
        Assert.Equal("event", h.P.World.Solver.Name)
        Return (h, lesson)
    End Function

    ''' <summary>Runs the presenter's frames until the world's clock reaches <paramref name="seconds"/>.</summary>
    Private Shared Sub RunTo(h As PresenterHarness, seconds As Double)
        Do While h.P.World.Time < seconds - 0.000000001
            h.P.Tick(Math.Min(1 / 60.0, seconds - h.P.World.Time))
        Loop
    End Sub

    Private Shared Function Text(value As Double, format As String) As String
        Return value.ToString(format, CultureInfo.InvariantCulture)
    End Function

    <Fact>
    Public Sub TerminalVelocity_EachBallReachesMgOverB_TheSpeedsTheCaptionStates()
        Dim opened = Open("terminal-velocity.json")
        Dim h = opened.H, w = h.P.World
        Dim balls = {w.Find("light"), w.Find("heavy")}
        Assert.True(balls(0).Mass < balls(1).Mass)
        RunTo(h, 1.5)
        For Each b In balls
            Assert.True(b.LinearDrag > 0)
            Dim terminal = b.Mass * G / b.LinearDrag
            Assert.Contains(Text(terminal, "0.00") & " m/s", opened.Lesson.Summary, StringComparison.Ordinal)
            ' v(t) = v_t (1 − e^(−t/τ)), τ = m/b: still falling, not yet on the floor.
            Dim tau = b.Mass / b.LinearDrag
            Assert.Equal(-terminal * (1 - Math.Exp(-w.Time / tau)), b.Velocity.Y, 6)
        Next
    End Sub

    <Fact>
    Public Sub ProjectileWithAndWithoutAir_TheBallWithDragLandsShort_WhereTheClosedFormSays()
        Dim opened = Open("projectile-air.json")
        Dim h = opened.H, w = h.P.World
        Dim vacuum = w.Find("vacuum"), air = w.Find("air")
        Assert.Equal(0.0, vacuum.LinearDrag)
        Assert.True(air.LinearDrag > 0)
        Assert.Equal(vacuum.Velocity, air.Velocity)
        Dim v0 = vacuum.Velocity, x0Vacuum = vacuum.CentreOfMass.X, x0Air = air.CentreOfMass.X
        Dim range = 2 * v0.X * v0.Y / G
        Assert.Contains(Text(range, "0.00") & " m", opened.Lesson.Summary, StringComparison.Ordinal)
        ' With drag: y(t) = (v0y + v_t) τ (1 − e^(−t/τ)) − v_t t returns to 0 at the landing time (bisection), x there is the range.
        Dim tau = air.Mass / air.LinearDrag, vt = G * tau
        Dim lo = 0.001, hi = 2 * v0.Y / G
        For k = 1 To 200
            Dim mid = (lo + hi) / 2
            If (v0.Y + vt) * tau * (1 - Math.Exp(-mid / tau)) - vt * mid > 0 Then lo = mid Else hi = mid
        Next
        Dim airRange = v0.X * tau * (1 - Math.Exp(-lo / tau))
        Assert.Contains(Text(airRange, "0.00") & " m", opened.Lesson.Summary, StringComparison.Ordinal)
        ' Just before landing both are still in the air, at the closed forms' x.
        RunTo(h, lo - 0.01)
        Assert.Equal(x0Air + v0.X * tau * (1 - Math.Exp(-w.Time / tau)), air.CentreOfMass.X, 6)
        Assert.Equal(x0Vacuum + v0.X * w.Time, vacuum.CentreOfMass.X, 6)
        Assert.True(air.CentreOfMass.Y > 0.1 + 0.000001)
        RunTo(h, lo + 0.05)
        ' Landed (e = 0): on the floor, where the closed form said, give or take the little it slid since.
        Assert.Equal(0.1, air.CentreOfMass.Y, 6)
        Assert.InRange(air.CentreOfMass.X - x0Air, airRange, airRange + 0.05 * v0.X)
    End Sub

    <Fact>
    Public Sub FloatingAndSinking_TheLightBoxesFloatAtMOverRhoW_TheDenseOneSinksToTheBottom()
        Dim opened = Open("floating-sinking.json")
        Dim h = opened.H, w = h.P.World
        Assert.Equal(1, w.Liquids.Count)
        Dim water = w.Liquids(0)
        Assert.Equal(1000.0, water.Density)
        Assert.True(water.LinearDrag > 0, "the water damps the bobbing, so the boxes settle")
        RunTo(h, 12.0)
        For Each id In {"cork", "oak"}
            Dim box = w.Find(id)
            Dim width = box.BoundsMax.X - box.BoundsMin.X
            Assert.True(box.Mass / (width * (box.BoundsMax.Y - box.BoundsMin.Y)) < water.Density)
            Dim depth = box.Mass / (water.Density * width)
            Assert.Contains(Text(depth, "0.00") & " m", opened.Lesson.Summary, StringComparison.Ordinal)
            Assert.True(Math.Abs(water.Surface - box.BoundsMin.Y - depth) < 0.001, $"{id}: depth {water.Surface - box.BoundsMin.Y} m, expected {depth} m")
        Next
        Dim brick = w.Find("brick")
        Assert.True(Math.Abs(brick.BoundsMin.Y - water.Min.Y) < 0.000001, $"brick's bottom at {brick.BoundsMin.Y} m")
        Assert.True(brick.Velocity.Length < 0.000001)
    End Sub

    <Fact>
    Public Sub BobbingBox_BobsAboutItsFloatingDepth_WithThePeriodTheCaptionStates()
        Dim opened = Open("bobbing-box.json")
        Dim h = opened.H, w = h.P.World
        Dim water = w.Liquids.Single()
        Assert.Equal(0.0, water.LinearDrag)
        Assert.Equal(0.0, water.DragCoefficient)
        Dim box = w.Find("box")
        Dim width = box.BoundsMax.X - box.BoundsMin.X
        Dim depth = box.Mass / (water.Density * width)
        Dim period = 2 * Math.PI * Math.Sqrt(box.Mass / (water.Density * G * width))
        Assert.Contains(Text(depth, "0.00") & " m", opened.Lesson.Summary, StringComparison.Ordinal)
        Assert.Contains(Text(period, "0.00") & " s", opened.Lesson.Summary, StringComparison.Ordinal)
        Dim start = water.Surface - box.BoundsMin.Y
        Assert.True(start < depth)
        ' Depth d(t) = d_f + (d0 − d_f) cos(2π t / T): after a whole number of periods it is back, half way it is deepest.
        RunTo(h, 3 * period)
        Assert.Equal(start, water.Surface - box.BoundsMin.Y, 6)
        RunTo(h, 3.5 * period)
        Assert.Equal(2 * depth - start, water.Surface - box.BoundsMin.Y, 6)
    End Sub
End Class
