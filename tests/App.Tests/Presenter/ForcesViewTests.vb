Option Strict On
Imports System.IO
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' The free-body diagram as the app shows it (<see cref="FreeBodyView"/>): on the inclined-plane lesson, the block
''' at rest feels its weight, the ramp's push m g cos θ and static friction m g sin θ, adding to zero; the block
''' sliding feels kinetic friction μk N, and ΣF reads the same as m a. Arrows, table rows and the trace.
''' </summary>
Public Class ForcesViewTests
    Private Const G As Double = 9.81
    Private Shared ReadOnly RestingNames As String() = {"weight", "normal", "friction"}
    Private Shared ReadOnly RestingSources As String() = {"Earth", "gentle", "gentle"}
    Private Shared ReadOnly Blocks As String() = {"stays", "slides"}
    Private Shared ReadOnly Gap As String() = {"    "}
    Private Shared ReadOnly ForceSymbols As String() = {"W", "N", "F"}

    Private Shared Function OpenInclinedPlane() As PresenterHarness
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.LessonFolder = Path.Combine(ProcessRunner.RepoRoot, "scenes")
        h.P.OpenLesson(h.P.Lessons().Single(Function(l) l.FileName = "inclined-plane.json"))
        Return h
    End Function

    Private Shared Function Angle(s As Segment) As Double
        Dim d = s.EndPoint - s.StartPoint
        Return Math.Atan(Math.Abs(d.Y / d.X))
    End Function

    <Fact>
    Public Sub BlockAtRestOnTheGentleRamp_WeightNormalAndStaticFriction_AddToZero()
        Dim h = OpenInclinedPlane()
        Dim theta = Angle(DirectCast(h.P.World.Find("gentle"), Segment))
        h.P.ChooseForcesBody("stays")
        Dim d = h.P.ForcesDiagram()
        Assert.Equal("stays", d.Body.Id)
        Dim rows = FreeBodyView.Rows(d)
        Assert.Equal(RestingNames, rows.Select(Function(r) r(0)).ToArray())
        Assert.Equal(RestingSources, rows.Select(Function(r) r(1)).ToArray())
        Assert.Equal(Units.Sig(G), rows(0)(2))
        Assert.Equal("270.0", rows(0)(3))
        Assert.Equal(Units.Sig(G * Math.Cos(theta)), rows(1)(2))
        Assert.Equal(Units.Sig(G * Math.Sin(theta)), rows(2)(2))
        ' The normal leans back from the vertical by θ; friction points up the slope, at θ.
        Assert.Equal(Units.Num(90 + theta * 180 / Math.PI, 1), rows(1)(3))
        Assert.Equal(Units.Num(theta * 180 / Math.PI, 1), rows(2)(3))
        Assert.Equal("ΣF = (0, 0) N    m·a = (0, 0) N", FreeBodyView.SumLine(d))
    End Sub

    <Fact>
    Public Sub BlockSlidingDownTheSteepRamp_KineticFrictionIsMuKN_AndTheSumIsMA()
        Dim h = OpenInclinedPlane()
        Dim w = h.P.World
        Dim theta = Angle(DirectCast(w.Find("steep"), Segment))
        ' Let it start sliding.
        Do While w.Time < 0.5
            h.P.Tick(1 / 60.0)
        Loop
        h.P.ChooseForcesBody("slides")
        Dim d = h.P.ForcesDiagram()
        Dim n = d.Forces.Single(Function(f) f.Kind = ForceKind.Normal)
        Dim fr = d.Forces.Single(Function(x) x.Kind = ForceKind.Friction)
        Assert.Equal(G * Math.Cos(theta), n.Magnitude, 9)
        Assert.Equal(w.Friction * n.Magnitude, fr.Magnitude, 9)
        Dim a = G * (Math.Sin(theta) - w.Friction * Math.Cos(theta))
        Assert.Equal(a, d.Acceleration.Length, 9)
        Assert.Equal(d.Sum.X, d.MassTimesAcceleration.X, 9)
        Assert.Equal(d.Sum.Y, d.MassTimesAcceleration.Y, 9)
        Dim line = FreeBodyView.SumLine(d)
        Dim halves = line.Split(Gap, StringSplitOptions.None)
        Assert.Equal(halves(0).Replace("ΣF", ""), halves(1).Replace("m·a", ""))
        Assert.NotEqual("ΣF = (0, 0) N    m·a = (0, 0) N", line)
    End Sub

    <Fact>
    Public Sub Arrows_StartAtTheCentreOfMass_TheLargestAsLongAsTheFractionOfTheContainer_Labelled()
        Dim h = OpenInclinedPlane()
        h.P.ChooseForcesBody("stays")
        Dim d = h.P.ForcesDiagram()
        Dim w = h.P.World
        Dim arrows = FreeBodyView.Arrows(d, w.Width, w.Height)
        Assert.Equal(3, arrows.Count)
        Dim c = d.Body.CentreOfMass
        For Each a In arrows
            Assert.Equal(c, a.Start)
        Next
        Dim weight = arrows(0)
        Assert.Equal("W " & Units.Quantity(G, "N"), weight.Label)
        ' The weight is the largest: its arrow is the longest wanted, straight down.
        Assert.Equal(FreeBodyView.LongestArrowFraction * Math.Min(w.Width, w.Height), (weight.Tip - weight.Start).Length, 12)
        Assert.Equal(c.X, weight.Tip.X, 12)
        Assert.StartsWith("N ", arrows(1).Label, StringComparison.Ordinal)
        Assert.StartsWith("F ", arrows(2).Label, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ShowingForces_WritesThemToTheTrace_AndAChosenBodyThatGoesFallsBackToTheFirst()
        Dim h = OpenInclinedPlane()
        Assert.False(h.P.Forces.Shown)
        h.P.SetShowForces(True)
        Assert.True(h.P.Forces.Shown)
        Assert.Contains("forces on", h.TraceLines)
        ' The first movable body unless another is chosen.
        Assert.StartsWith("forces of stays: W Earth 9.810 N 270.0°; N gentle ", h.TraceLines.Last(), StringComparison.Ordinal)
        Assert.EndsWith("| sum (0.000, 0.000) N ma (0.000, 0.000) N", h.TraceLines.Last(), StringComparison.Ordinal)
        h.P.ChooseForcesBody("nothing-by-that-name")
        Assert.Equal("stays", h.P.ForcesDiagram().Body.Id)
        Assert.Equal(Blocks, h.P.ForcesBodies().ToArray())
    End Sub

    <Fact>
    Public Sub ForcesOn_EachArrowAndTheSumAreLabelledOnTheCanvas_NoLabelOverAnotherOrABody()
        Dim h = OpenInclinedPlane()
        h.P.CanvasResized(800, 500)
        Dim measure = Function(text As String) As (Width As Double, Height As Double)
                          Return (8.0 * text.Length + 2, 16.0)
                      End Function
        Assert.DoesNotContain(h.P.LayOutLabels(measure, 800, 500), Function(l) l.Kind = CanvasLabelKind.Force OrElse l.Kind = CanvasLabelKind.ForceSum)
        h.P.SetShowForces(True)
        Dim labels = h.P.LayOutLabels(measure, 800, 500)
        Dim forces = labels.Where(Function(l) l.Kind = CanvasLabelKind.Force).Select(Function(l) l.Text.Split(" "c)(0)).ToArray()
        Assert.Equal(ForceSymbols, forces)
        Assert.Single(labels, Function(l) l.Kind = CanvasLabelKind.ForceSum AndAlso l.Text = "ΣF = (0, 0) N    m·a = (0, 0) N")
        For i = 0 To labels.Count - 1
            For j = i + 1 To labels.Count - 1
                Assert.False(labels(i).Box.Overlaps(labels(j).Box), $"'{labels(i).Text}' and '{labels(j).Text}' overlap")
            Next
            For Each b In h.P.World.Bodies
                If b.Kind = ShapeKind.Segment OrElse (labels(i).Inside AndAlso b Is labels(i).Body) Then Continue For
                Assert.False(labels(i).Box.Overlaps(CanvasLabelLayout.ScreenBox(b, h.P.View, 1.0)), $"'{labels(i).Text}' covers {b.Id}")
            Next
        Next
        Assert.Equal(3, h.P.ForceArrows().Count)
        h.P.SetShowForces(False)
        Assert.Empty(h.P.ForceArrows())
    End Sub
End Class
