Option Strict On
Imports System.IO
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The friction lessons of the Scenes menu, opened in the app (event solver) and checked against what their captions claim.</summary>
Public Class FrictionLessonsTests
    Private Const G As Double = 9.81

    Private Shared Function Open(fileName As String) As (H As PresenterHarness, Lesson As Lesson)
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.LessonFolder = Path.Combine(ProcessRunner.RepoRoot, "scenes")
        Dim lesson = h.P.Lessons().Single(Function(l) l.FileName = fileName)
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

    ''' <summary>A ramp's angle above the horizontal, radians.</summary>
    Private Shared Function Angle(s As Segment) As Double
        Dim d = s.EndPoint - s.StartPoint
        Return Math.Atan(Math.Abs(d.Y / d.X))
    End Function

    <Fact>
    Public Sub InclinedPlane_TheBlockBelowTheAngleOfReposeStays_TheOneAboveSlidesAtGSinMinusMuCos()
        Dim opened = Open("inclined-plane.json")
        Dim h = opened.H, w = h.P.World
        Dim muS = w.StaticFriction.Value, mu = w.Friction
        Dim gentle = Angle(DirectCast(w.Find("gentle"), Segment)), steep = Angle(DirectCast(w.Find("steep"), Segment))
        ' The caption's angle of repose, and the two ramps either side of it.
        Dim repose = Math.Atan(muS) * 180 / Math.PI
        Assert.Contains("tan⁻¹ μs = " & repose.ToString("0.0", Globalization.CultureInfo.InvariantCulture) & "°", opened.Lesson.Summary, StringComparison.Ordinal)
        Assert.True(Math.Tan(gentle) < muS AndAlso Math.Tan(steep) > muS)
        Dim a = G * (Math.Sin(steep) - mu * Math.Cos(steep))
        Assert.Contains(a.ToString("0.00", Globalization.CultureInfo.InvariantCulture) & " m/s²", opened.Lesson.Summary, StringComparison.Ordinal)
        Dim stays = w.Find("stays"), slides = w.Find("slides")
        Dim stays0 = stays.CentreOfMass, slides0 = slides.CentreOfMass
        ' Down the steep ramp, which falls to the right.
        Dim down = New Vector(Math.Cos(steep), -Math.Sin(steep))
        RunTo(h, 1.0)
        Dim s = 0.5 * a * w.Time * w.Time
        Assert.Equal(slides0.X + down.X * s, slides.CentreOfMass.X, 6)
        Assert.Equal(slides0.Y + down.Y * s, slides.CentreOfMass.Y, 6)
        RunTo(h, 2.0)
        ' Held by static friction: not moved at all.
        Assert.Equal(stays0, stays.CentreOfMass)
        Assert.Equal(Vector.Zero, stays.Velocity)
        Assert.True((slides.CentreOfMass - slides0).Length > 2.0, $"slid only {(slides.CentreOfMass - slides0).Length} m")
    End Sub

    <Fact>
    Public Sub RoughFloor_EachBlockStopsAfterVSquaredOverTwoMuG_AtVOverMuG_WhateverItsMass()
        Dim opened = Open("rough-floor.json")
        Dim h = opened.H, w = h.P.World
        Dim mu = w.Friction
        Dim blocks = {w.Find("light"), w.Find("heavy")}
        Assert.NotEqual(blocks(0).Mass, blocks(1).Mass)
        Dim starts = blocks.Select(Function(b) b.CentreOfMass.X).ToArray()
        Dim v = blocks(0).Velocity.X
        Assert.Equal(v, blocks(1).Velocity.X)
        Dim distance = v * v / (2 * mu * G), stops = v / (mu * G)
        Assert.Contains(distance.ToString("0.00", Globalization.CultureInfo.InvariantCulture) & " m", opened.Lesson.Summary, StringComparison.Ordinal)
        Assert.Contains(stops.ToString("0.00", Globalization.CultureInfo.InvariantCulture) & " s", opened.Lesson.Summary, StringComparison.Ordinal)
        ' Half way in time it is still sliding, as x = v t − ½ μk g t² says.
        RunTo(h, stops / 2)
        For i = 0 To 1
            Assert.Equal(starts(i) + v * w.Time - 0.5 * mu * G * w.Time * w.Time, blocks(i).CentreOfMass.X, 6)
        Next
        RunTo(h, 3.0)
        For i = 0 To 1
            Assert.Equal(starts(i) + distance, blocks(i).CentreOfMass.X, 6)
            Assert.True(Math.Abs(blocks(i).Velocity.X) <= 0.000000001, $"{blocks(i).Id}: {blocks(i).Velocity.X} m/s")
        Next
    End Sub
End Class
