Option Strict On
Imports System.Text.Json
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Scenes
Imports Xunit
Imports Xunit.Abstractions

''' <summary>The scene generator: every scene loads, a seed gives one scene, and the mix covers what it promises.</summary>
Public Class GeneratorTests
    Private Const Seeds As Integer = 1000
    Private Const MaxBodies As Integer = 40
    Private Const Touch As Double = 0.000000001 ' m: what counts as touching (the format's overlap tolerance)
    Private ReadOnly _output As ITestOutputHelper

    Public Sub New(output As ITestOutputHelper)
        _output = output
    End Sub

    <Fact>
    Public Sub EveryScene_LoadsWithTheSceneReader_AndHoldsOnlyTheDefaultKinds()
        For seed = 1 To Seeds
            Dim draft = SceneGenerator.Generate(seed, BodyKinds.Default, MaxBodies)
            Dim text = draft.ToText()
            Dim world As World = Nothing
            Try
                world = SceneFile.Load(text)
            Catch ex As SceneFormatException
                Assert.Fail($"seed {seed}: the reader refuses the scene: {ex.Message}{vbLf}{text}")
            End Try
            Assert.Equal(draft.Bodies.Count, world.Bodies.Count)
            Assert.True(world.Circles.Any(Function(c) Not c.IsFixed), $"seed {seed}: nothing can move")
            Using doc = JsonDocument.Parse(text)
                Assert.False(doc.RootElement.TryGetProperty("links", Nothing), $"seed {seed}: links are off by default")
                For Each b In doc.RootElement.GetProperty("bodies").EnumerateArray()
                    Dim type = b.GetProperty("type").GetString()
                    Assert.True(type = "circle" OrElse type = "rectangle", $"seed {seed}: type {type} is off by default")
                    If type = "rectangle" Then Assert.False(b.TryGetProperty("fixed", Nothing), $"seed {seed}: movable boxes are off by default")
                Next
            End Using
        Next
    End Sub

    <Fact>
    Public Sub RoughScenes_HaveFrictionTheReaderTakes_AndTheSameBodies()
        Dim rough = 0
        For seed = 1 To 200
            Dim plain = SceneGenerator.Generate(seed, BodyKinds.All, MaxBodies)
            Dim some = SceneGenerator.Generate(seed, BodyKinds.All, MaxBodies, 0.5)
            Assert.Equal(plain.ToText(), SceneGenerator.Generate(seed, BodyKinds.All, MaxBodies, 0).ToText())
            Dim world = SceneFile.Load(some.ToText())
            If some.World.Friction > 0 Then
                rough += 1
                Assert.Equal(some.World.Friction, world.Friction)
                Dim mus = world.StaticFriction.GetValueOrDefault(world.Friction)
                Assert.True(mus >= world.Friction AndAlso mus <= 1.5 * world.Friction, $"seed {seed}: μs {mus}")
            Else
                Assert.Equal(0.0, world.Friction)
            End If
            ' Friction or not, the bodies are the same.
            Assert.Equal(plain.Bodies.Select(Function(b) b.ToJson()), some.Bodies.Select(Function(b) b.ToJson()))
        Next
        Assert.InRange(rough, 70, 130)
    End Sub

    <Fact>
    Public Sub TheSameSeed_GivesTheSameScene_BitForBit()
        For seed = 1 To 200
            Dim first = SceneGenerator.Generate(seed, BodyKinds.Default, MaxBodies).ToText()
            Dim again = SceneGenerator.Generate(seed, BodyKinds.Default, MaxBodies).ToText()
            Assert.Equal(first, again)
            ' and what the reader makes of it, to the bit
            Dim a = SceneFile.Load(first), b = SceneFile.Load(again)
            For i = 0 To a.Circles.Count - 1
                Assert.Equal(BitConverter.DoubleToInt64Bits(a.Circles(i).Position.X), BitConverter.DoubleToInt64Bits(b.Circles(i).Position.X))
                Assert.Equal(BitConverter.DoubleToInt64Bits(a.Circles(i).Velocity.Y), BitConverter.DoubleToInt64Bits(b.Circles(i).Velocity.Y))
            Next
        Next
        Dim all = Enumerable.Range(1, 200).Select(Function(s) SceneGenerator.Generate(s, BodyKinds.Default, MaxBodies).ToText()).ToList()
        Assert.Equal(200, all.Distinct().Count())
    End Sub

    <Fact>
    Public Sub OverAThousandSeeds_TheMixCoversEveryIngredient()
        Dim c As New Tally()
        Dim count = Sub(key As String) c.Add(key)
        Dim minRadius = Double.PositiveInfinity, maxRadius = 0.0, minMass = Double.PositiveInfinity, maxMass = 0.0, maxSpeed = 0.0
        Dim widestMassSpread = 1.0
        For seed = 1 To Seeds
            Dim draft = SceneGenerator.Generate(seed, BodyKinds.Default, MaxBodies)
            For Each name In draft.Ingredients.Distinct()
                count("ingredient " & name)
            Next
            Dim w = SceneFile.Load(draft.ToText())
            Dim side = Math.Min(w.Width, w.Height)
            If side < 0.5 Then count("container under 0.5 m")
            If side >= 100 Then count("container of 100 m or more")
            If w.Gravity = 0 Then count("g = 0")
            If w.Gravity = 100 Then count("g = 100")
            If w.Gravity > 0 AndAlso w.Gravity < 100 Then count("0 < g < 100")
            If w.Restitution = 0 Then count("e = 0")
            If w.Restitution = 1 Then count("e = 1")
            If w.Restitution > 0 AndAlso w.Restitution < 1 Then count("0 < e < 1")
            If Not w.Walls Then count("walls off")
            Dim movable = w.Circles.Where(Function(x) Not x.IsFixed).ToList()
            For Each ball In movable
                minRadius = Math.Min(minRadius, ball.Radius)
                maxRadius = Math.Max(maxRadius, ball.Radius)
                minMass = Math.Min(minMass, ball.Mass)
                maxMass = Math.Max(maxMass, ball.Mass)
                maxSpeed = Math.Max(maxSpeed, ball.Velocity.Length)
                If ball.Velocity = Vector.Zero Then count("balls at rest")
            Next
            widestMassSpread = Math.Max(widestMassSpread, movable.Max(Function(x) x.Mass) / movable.Min(Function(x) x.Mass))
            If movable.Any(Function(x) x.Velocity.Length >= 1000) Then count("a ball at 1000 m/s or more")
            If w.Circles.Any(Function(x) x.IsFixed) Then count("fixed circles")
            If w.Rectangles.Count > 0 Then count("rectangles")
            If w.Rectangles.Any(Function(r) r.Min.X < 0 OrElse r.Min.Y < 0 OrElse r.Max.X > w.Width OrElse r.Max.Y > w.Height) Then count("a rectangle partly outside")
            If TouchingPairs(w) > 0 Then count("touching circles")
            If HasTouchingRow(w) Then count("a row of three touching balls")
            If HasTouchingTriangle(w) Then count("three mutually touching balls (a stack)")
            If movable.Any(Function(b) w.Rectangles.Any(Function(r) OnTop(b, r))) Then count("a ball exactly on a rectangle's top")
            If movable.Any(Function(b) w.Rectangles.Any(Function(r) OnCorner(b, r))) Then count("a ball exactly on a rectangle's corner")
            If movable.Any(Function(b) w.Circles.Any(Function(f) f.IsFixed AndAlso f.Position.Y < b.Position.Y AndAlso Math.Abs((b.Position - f.Position).Length - b.Radius - f.Radius) <= Touch)) Then count("a ball exactly on a fixed circle")
            If w.Walls AndAlso movable.Any(Function(b) Math.Abs(b.Position.Y - b.Radius) <= Touch) Then count("a ball exactly on the floor")
        Next
        For Each key In c.Keys
            _output.WriteLine($"{key}: {c.Of(key)} of {Seeds} scenes")
        Next
        _output.WriteLine($"radii {minRadius} to {maxRadius} m, masses {minMass} to {maxMass} kg (widest spread in one scene {widestMassSpread:G3}), fastest {maxSpeed} m/s")
        Dim atLeast = Sub(key As String, n As Integer) Assert.True(c.Of(key) >= n, $"{key}: {c.Of(key)} scenes, expected at least {n}")
        ' Expected shares from the generator's odds, with room for chance: g = 0 in 30 %, g = 100 in 15 %, e = 0 in 20 %,
        ' e = 1 in 25 %, walls off in 20 %, centimetre and kilometre containers in 10 % each, obstacles in half the scenes.
        atLeast("g = 0", 220)
        atLeast("g = 100", 100)
        atLeast("0 < g < 100", 400)
        atLeast("e = 0", 140)
        atLeast("e = 1", 180)
        atLeast("0 < e < 1", 400)
        atLeast("walls off", 140)
        atLeast("container under 0.5 m", 60)
        atLeast("container of 100 m or more", 60)
        atLeast("fixed circles", 300)
        atLeast("rectangles", 300)
        atLeast("a rectangle partly outside", 100)
        atLeast("touching circles", 200)
        atLeast("a row of three touching balls", 50)
        atLeast("three mutually touching balls (a stack)", 30)
        atLeast("a ball exactly on a rectangle's top", 50)
        atLeast("a ball exactly on a rectangle's corner", 50)
        atLeast("a ball exactly on a fixed circle", 50)
        atLeast("a ball exactly on the floor", 100)
        ' A scene's top speed is log-uniform over six decades up to 10⁴ m/s (1000 m/s or more in one scene in
        ' six), and its balls log-uniform over three decades below that: about one scene in fifteen.
        atLeast("a ball at 1000 m/s or more", 40)
        atLeast("balls at rest", 1000)
        atLeast("ingredient pile", 50)
        atLeast("ingredient scatter", 500)
        Assert.True(minRadius <= 0.001, $"smallest radius {minRadius} m")
        Assert.True(maxRadius >= 1.5, $"largest radius {maxRadius} m")
        Assert.True(maxMass / minMass >= 1.0E+11, $"masses from {minMass} to {maxMass} kg")
        Assert.True(widestMassSpread >= 1.0E+10, $"widest mass spread in one scene {widestMassSpread}")
        Assert.True(maxSpeed >= 5000, $"fastest {maxSpeed} m/s")
    End Sub

    <Fact>
    Public Sub TheKindsTheEngineDoesNotReadYet_AreWrittenToTheSpecification()
        Dim c As New Tally()
        Dim count = Sub(key As String) c.Add(key)
        For seed = 1 To 500
            Dim text = SceneGenerator.Generate(seed, BodyKinds.All, MaxBodies).ToText()
            Dim problems = SpecConformance.Problems(text)
            Assert.True(problems.Count = 0, $"seed {seed}: {String.Join("; ", problems)}{vbLf}{text}")
            Assert.Equal(text, SceneGenerator.Generate(seed, BodyKinds.All, MaxBodies).ToText())
            Using doc = JsonDocument.Parse(text)
                For Each b In doc.RootElement.GetProperty("bodies").EnumerateArray()
                    Dim type = b.GetProperty("type").GetString()
                    Dim fixedElement As JsonElement
                    Dim isFixed = If(b.TryGetProperty("fixed", fixedElement), fixedElement.GetBoolean(), type <> "circle" AndAlso type <> "polygon")
                    count(type & If(isFixed, " fixed", " movable"))
                Next
                Dim links As JsonElement
                If doc.RootElement.TryGetProperty("links", links) Then
                    For Each l In links.EnumerateArray()
                        count("link " & l.GetProperty("type").GetString() & If(l.TryGetProperty("at", Nothing), " to a point", " to a body"))
                    Next
                End If
            End Using
        Next
        For Each key In c.Keys
            _output.WriteLine($"{key}: {c.Of(key)}")
        Next
        For Each key In {"segment fixed", "polygon fixed", "polygon movable", "rectangle movable", "rectangle fixed", "circle movable", "circle fixed",
                         "link spring to a body", "link spring to a point", "link rod to a body", "link rod to a point", "link string to a body", "link string to a point"}
            Assert.True(c.Of(key) >= 20, $"{key}: {c.Of(key)}")
        Next
    End Sub

    <Fact>
    Public Sub Kinds_ReadAsTheCommandLineSpellsThem()
        Assert.Equal(BodyKinds.Default, BodyKindNames.Parse("circle,rectangle"))
        Assert.Equal(BodyKinds.All, BodyKindNames.Parse("all"))
        Assert.Equal(BodyKinds.Circle Or BodyKinds.Segment, BodyKindNames.Parse("segment, circle"))
        Assert.Equal(BodyKinds.Default, BodyKindNames.Parse(BodyKindNames.Format(BodyKinds.Default)))
        Assert.Throws(Of ArgumentException)(Function() BodyKindNames.Parse("circle,blob"))
        ' a kind switched off never appears, even where an ingredient would add it
        For seed = 1 To 100
            Dim draft = SceneGenerator.Generate(seed, BodyKinds.Circle, MaxBodies)
            Assert.True(draft.Bodies.All(Function(b) b.Shape = DraftShape.Circle), $"seed {seed}")
        Next
    End Sub

    Private Shared Function TouchingPairs(w As World) As Integer
        Dim n = 0
        For i = 0 To w.Circles.Count - 1
            For j = i + 1 To w.Circles.Count - 1
                Dim a = w.Circles(i), b = w.Circles(j)
                If a.IsFixed AndAlso b.IsFixed Then Continue For
                If Math.Abs((a.Position - b.Position).Length - a.Radius - b.Radius) <= Touch Then n += 1
            Next
        Next
        Return n
    End Function

    Private Shared Function Touching(a As Circle, b As Circle) As Boolean
        Return a IsNot b AndAlso Math.Abs((a.Position - b.Position).Length - a.Radius - b.Radius) <= Touch
    End Function

    ''' <summary>Three equal balls in a line, each touching the next (a cradle).</summary>
    Private Shared Function HasTouchingRow(w As World) As Boolean
        For Each middle In w.Circles
            Dim near = w.Circles.Where(Function(x) Touching(x, middle) AndAlso x.Radius = middle.Radius).ToList()
            For i = 0 To near.Count - 1
                For j = i + 1 To near.Count - 1
                    Dim u = near(i).Position - middle.Position, v = near(j).Position - middle.Position
                    If Math.Abs(Vector.Cross(u, v)) <= 0.000001 * u.Length * v.Length AndAlso Vector.Dot(u, v) < 0 Then Return True
                Next
            Next
        Next
        Return False
    End Function

    Private Shared Function HasTouchingTriangle(w As World) As Boolean
        Dim movable = w.Circles.Where(Function(x) Not x.IsFixed).ToList()
        For Each a In movable
            Dim near = movable.Where(Function(x) Touching(x, a)).ToList()
            For i = 0 To near.Count - 1
                For j = i + 1 To near.Count - 1
                    If Touching(near(i), near(j)) Then Return True
                Next
            Next
        Next
        Return False
    End Function

    Private Shared Function OnTop(b As Circle, r As Rectangle) As Boolean
        Return Math.Abs(b.Position.Y - b.Radius - r.Max.Y) <= Touch AndAlso b.Position.X >= r.Min.X AndAlso b.Position.X <= r.Max.X
    End Function

    Private Shared Function OnCorner(b As Circle, r As Rectangle) As Boolean
        For Each corner In {r.Min, r.Max, New Vector(r.Min.X, r.Max.Y), New Vector(r.Max.X, r.Min.Y)}
            If Math.Abs((b.Position - corner).Length - b.Radius) <= Touch Then Return True
        Next
        Return False
    End Function
End Class
