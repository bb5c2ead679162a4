Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Saving then loading gives back exactly the same links: every kind, both kinds of end, any body kind.</summary>
Public Class SceneLinkRoundTripTests
    <Fact>
    Public Sub EveryKind_ToABody_AFixedBody_AndAPoint_SurvivesSaveAndLoad()
        Dim w = EveryBodyKind()
        Dim ball = w.Find("ball"), box = w.Find("box"), tri = w.Find("tri"), peg = w.Find("peg"), table = w.Find("table"), wedge = w.Find("wedge")
        w.Add(Link.CreateSpring(ball, box, 37.25, 0.1 + 0.2, 0.3, "s-body"))
        w.Add(Link.CreateSpring(tri, table, 1.0E-300, 0, 0, "s-fixed"))
        w.Add(Link.CreateSpring(box, New Vector(-1.0E-17, 123456.789), 1.0E+300, Math.PI, Math.E))
        w.Add(Link.CreateTie(LinkKind.Rod, ball, tri, (tri.CentreOfMass - ball.CentreOfMass).Length, "rod-body"))
        w.Add(Link.CreateTie(LinkKind.Rod, box, wedge, (wedge.CentreOfMass - box.CentreOfMass).Length))
        w.Add(Link.CreateTie(LinkKind.Rod, tri, New Vector(0.7, 4.9), (New Vector(0.7, 4.9) - tri.CentreOfMass).Length, "rod-point"))
        w.Add(Link.CreateTie(LinkKind.String, box, ball, (ball.CentreOfMass - box.CentreOfMass).Length * 1.7, "string-body"))
        w.Add(Link.CreateTie(LinkKind.String, ball, peg, (peg.CentreOfMass - ball.CentreOfMass).Length, "string-fixed"))
        ' Exactly the distance: the triangle's centroid, found again from its saved corners, may move by a rounding.
        w.Add(Link.CreateTie(LinkKind.String, tri, New Vector(1.0 / 3, 2.0 / 3), (New Vector(1.0 / 3, 2.0 / 3) - tri.CentreOfMass).Length, "string-point"))
        Dim text = SceneFile.Save(w)
        Dim loaded = SceneFile.Load(text)
        AssertSameLinks(w, loaded, text)
        Assert.Equal("s-body|s-fixed|link1|rod-body|link2|rod-point|string-body|string-fixed|string-point", String.Join("|", loaded.Links.Select(Function(l) l.Id)))
        Assert.Equal(text, SceneFile.Save(loaded))
    End Sub

    <Fact>
    Public Sub RandomScenesWithLinks_SurviveSaveAndLoad_BitForBit()
        For seed = 1 To 200
            Dim original = SceneRoundTripTests.RandomScene(seed)
            AddRandomLinks(original, New Random(seed))
            Dim text = SceneFile.Save(original)
            Dim loaded = SceneFile.Load(text)
            Dim context = "seed " & seed.ToString(CultureInfo.InvariantCulture) & vbLf & text
            SceneRoundTripTests.AssertSameScene(original, loaded, context)
            AssertSameLinks(original, loaded, context)
            Assert.Equal(text, SceneFile.Save(loaded))
        Next
    End Sub

    <Fact>
    Public Sub LengthsSurviveASave_AfterTheBodiesMoved()
        ' Loaded with every length left out: each is the distance in this file.
        Dim w = SceneFile.Load(SceneErrorTests.Q("{'format':'physics-scene/1','world':{'width':8,'height':5,'gravity':0},'bodies':[" &
            "{'id':'bob','type':'circle','x':4,'y':2.5,'radius':0.1,'mass':1},{'id':'other','type':'circle','x':6,'y':2.5,'radius':0.1,'mass':1}]," &
            "'links':[{'type':'rod','a':'bob','at':[4,4]},{'type':'spring','a':'other','b':'bob','stiffness':10},{'type':'string','a':'other','at':[6,4.5]}]}"))
        Assert.Equal(1.5, w.Links(0).Length)
        Assert.Equal(2.0, w.Links(1).Length)
        Assert.Equal(2.0, w.Links(2).Length)
        ' The pendulum swings 30° and "other" moves up 1 m: the rod keeps its 1.5 m, the spring is squashed, the string slack.
        Dim bob = w.Find("bob"), other = w.Find("other")
        bob.Position = New Vector(4 + 1.5 * Math.Sin(Math.PI / 6), 4 - 1.5 * Math.Cos(Math.PI / 6))
        other.Position = New Vector(6, 3.5)
        Assert.True(Math.Abs(w.Links(0).Distance - 1.5) < 0.000000000001)
        Assert.True(w.Links(1).Distance < 2.0 - 0.1)
        Assert.True(w.Links(2).Distance < 2.0 - 0.9)
        Dim loaded = SceneFile.Load(SceneFile.Save(w))
        Assert.Equal(1.5, loaded.Links(0).Length)
        Assert.Equal(2.0, loaded.Links(1).Length)
        Assert.Equal(2.0, loaded.Links(2).Length)
        Assert.Equal(bob.Position, loaded.Find("bob").Position)
    End Sub

    <Fact>
    Public Sub AWorldWithoutLinks_IsWrittenWithoutALinksField()
        Assert.DoesNotContain("""links""", SceneFile.Save(Scenarios.Demo()))
    End Sub

    <Fact>
    Public Sub Save_WritesEveryLinkFieldPlainly()
        Dim w = EveryBodyKind()
        w.Add(Link.CreateSpring(w.Find("ball"), New Vector(2, 4.5), 40, 0.5, 0))
        w.Add(Link.CreateTie(LinkKind.Rod, w.Find("box"), w.Find("table"), (w.Find("table").CentreOfMass - w.Find("box").CentreOfMass).Length, "bar"))
        Dim text = SceneFile.Save(w)
        Assert.Contains("""links"": [", text)
        Assert.Contains("""id"": ""link1""", text)
        Assert.Contains("""type"": ""spring""", text)
        Assert.Contains("""at"": [", text)
        Assert.Contains("""stiffness"": 40", text)
        Assert.Contains("""rest_length"": 0.5", text)
        Assert.Contains("""damping"": 0", text)
        Assert.Contains("""type"": ""rod""", text)
        Assert.Contains("""a"": ""box""", text)
        Assert.Contains("""b"": ""table""", text)
        Assert.Contains("""length"": ", text)
    End Sub

    ''' <summary>A movable circle, box and triangle, and a fixed circle, rectangle and triangle, apart, in an 8 × 5 m box.</summary>
    Private Shared Function EveryBodyKind() As World
        Dim w As New World(8, 5, 9.81, 0.8, True)
        w.Add(New Circle(New Vector(1.1, 2.2), 0.15, 0.7, New Vector(0.3, -0.1), "ball"))
        w.Add(Rectangle.CreateMovable(New Vector(3.3, 0.1), 0.7, 0.3, 2.5, New Vector(-1, 0), "box"))
        w.Add(New Polygon({New Vector(1.1, 3.3), New Vector(2.2, 3.4), New Vector(1.7, 4.4)}, 1.3, Vector.Zero, "tri"))
        w.Add(Circle.CreateFixed(New Vector(5.5, 4.1), 0.2, "peg"))
        w.Add(New Rectangle(New Vector(6.1, 0), 1.3, 0.9, "table"))
        w.Add(Polygon.CreateFixed({New Vector(4.4, 2.2), New Vector(5.1, 2.3), New Vector(4.6, 3.1)}, "wedge"))
        Return w
    End Function

    ''' <summary>
    ''' Up to six links from movable bodies to other bodies or to points; rods as long as their ends are apart,
    ''' strings at least that long, springs with any rest length, stiffness and damping.
    ''' </summary>
    Private Shared Sub AddRandomLinks(w As World, rng As Random)
        Dim movables = w.Movables
        If movables.Count = 0 Then Return
        For i = 1 To rng.Next(0, 7)
            Dim a = movables(rng.Next(movables.Count))
            Dim others = w.Bodies.Where(Function(body) body IsNot a).ToList()
            Dim b As Shape = If(others.Count > 0 AndAlso rng.Next(2) = 0, others(rng.Next(others.Count)), Nothing)
            Dim anchor = New Vector((rng.NextDouble() - 0.25) * w.Width * 2, (rng.NextDouble() - 0.25) * w.Height * 2)
            Dim endB = If(b Is Nothing, anchor, b.CentreOfMass)
            Dim distance = (endB - a.CentreOfMass).Length
            Dim id = If(rng.Next(3) = 0, "", "L" & rng.Next(1000).ToString(CultureInfo.InvariantCulture) & "\/""é")
            If id.Length > 0 AndAlso w.FindLink(id) IsNot Nothing Then id = ""
            Dim link As Link
            Select Case rng.Next(3)
                Case 0
                    Dim stiffness = Math.Exp(rng.NextDouble() * 20 - 5)
                    Dim rest = If(rng.Next(4) = 0, 0.0, distance * rng.NextDouble() * 2)
                    Dim damping = If(rng.Next(2) = 0, 0.0, rng.NextDouble() * 3)
                    link = If(b Is Nothing, Link.CreateSpring(a, anchor, stiffness, rest, damping, id), Link.CreateSpring(a, b, stiffness, rest, damping, id))
                Case 1
                    If distance = 0 Then Continue For
                    link = If(b Is Nothing, Link.CreateTie(LinkKind.Rod, a, anchor, distance, id), Link.CreateTie(LinkKind.Rod, a, b, distance, id))
                Case Else
                    Dim length = Math.Max(distance, 0.001) * (1 + rng.NextDouble())
                    link = If(b Is Nothing, Link.CreateTie(LinkKind.String, a, anchor, length, id), Link.CreateTie(LinkKind.String, a, b, length, id))
            End Select
            w.Add(link)
        Next
    End Sub

    Private Shared Sub AssertSameLinks(a As World, b As World, context As String)
        Assert.True(a.Links.Count = b.Links.Count, "link count differs: " & context)
        For i = 0 To a.Links.Count - 1
            Dim x = a.Links(i), y = b.Links(i)
            Dim where = "link " & i.ToString(CultureInfo.InvariantCulture) & ": " & context
            Assert.True(x.Id = y.Id, "id differs (" & x.Id & " / " & y.Id & "), " & where)
            Assert.True(x.Kind = y.Kind, "kind differs, " & where)
            Assert.True(x.A.Id = y.A.Id AndAlso y.A Is b.Find(x.A.Id), "end a differs, " & where)
            Assert.True((x.B Is Nothing) = (y.B Is Nothing), "end b's kind differs, " & where)
            If x.B IsNot Nothing Then Assert.True(x.B.Id = y.B.Id AndAlso y.B Is b.Find(x.B.Id), "end b differs, " & where)
            Assert.True(Same(x.Anchor.X, y.Anchor.X) AndAlso Same(x.Anchor.Y, y.Anchor.Y), "anchor differs, " & where)
            Assert.True(Same(x.Length, y.Length), "length differs, " & where)
            Assert.True(Same(x.Stiffness, y.Stiffness), "stiffness differs, " & where)
            Assert.True(Same(x.Damping, y.Damping), "damping differs, " & where)
        Next
    End Sub

    ''' <summary>Bit for bit, so -0 and 0 differ.</summary>
    Private Shared Function Same(a As Double, b As Double) As Boolean
        Return BitConverter.DoubleToInt64Bits(a) = BitConverter.DoubleToInt64Bits(b)
    End Function
End Class
