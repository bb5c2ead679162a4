Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Saving then loading gives back exactly the same scene, for many random scenes.</summary>
Public Class SceneRoundTripTests
    <Fact>
    Public Sub RandomScenes_SurviveSaveAndLoad_BitForBit()
        For seed = 1 To 300
            Dim original = RandomScene(seed)
            Dim text = SceneFile.Save(original)
            Dim loaded = SceneFile.Load(text)
            AssertSameScene(original, loaded, "seed " & seed.ToString(CultureInfo.InvariantCulture) & vbLf & text)
            ' Writing is deterministic: the loaded scene saves to the same text.
            Assert.Equal(text, SceneFile.Save(loaded))
        Next
    End Sub

    <Fact>
    Public Sub Demo_SurvivesSaveAndLoad()
        Dim original = Scenarios.Demo()
        AssertSameScene(original, SceneFile.Load(SceneFile.Save(original)), "demo")
    End Sub

    <Fact>
    Public Sub Save_WritesTheFormatPlainly_AndEveryField()
        Dim text = SceneFile.Save(Scenarios.Demo())
        Assert.Contains("""format"": ""physics-scene/1""", text)
        Assert.Contains("""id"": ""table""", text)
        Assert.Contains("""color"": ""#e53935""", text)
        Assert.Contains("""restitution"": 0.9", text)
        Assert.Contains("""walls"": true", text)
        Assert.Contains("""fixed"": true", text)
    End Sub

    ''' <summary>A scene with every kind of body, awkward ids and numbers that need all 17 digits.</summary>
    Friend Shared Function RandomScene(seed As Integer) As World
        Dim rng As New Random(seed)
        Dim walls = rng.Next(3) > 0
        Dim w As New World(Awkward(rng, 1, 50), Awkward(rng, 1, 50), If(rng.Next(5) = 0, 0.0, Awkward(rng, 0, 30)),
                           If(rng.Next(4) = 0, 1.0, rng.NextDouble()), walls)
        ' one body per grid cell, so nothing overlaps
        Dim cols = 6, rows = 6
        Dim cw = w.Width / cols, ch = w.Height / rows
        Dim count = rng.Next(0, cols * rows)
        Dim cells = Enumerable.Range(0, cols * rows).OrderBy(Function(i) rng.Next()).Take(count).ToList()
        For Each cell In cells
            Dim cx = (cell Mod cols) * cw, cy = (cell \ cols) * ch
            Dim id = If(rng.Next(4) = 0, Nothing, RandomId(rng))
            If id IsNot Nothing AndAlso w.Find(id) IsNot Nothing Then id = Nothing
            Dim body As Shape
            Select Case rng.Next(3)
                Case 0
                    Dim r = Math.Min(cw, ch) * (0.05 + 0.4 * rng.NextDouble())
                    Dim pos = New Vector(cx + cw / 2 + (rng.NextDouble() - 0.5) * (cw - 2 * r), cy + ch / 2 + (rng.NextDouble() - 0.5) * (ch - 2 * r))
                    body = New Circle(pos, r, Awkward(rng, 0.001, 100), New Vector(Velocity(rng), Velocity(rng)), id)
                Case 1
                    Dim r = Math.Min(cw, ch) * (0.05 + 0.4 * rng.NextDouble())
                    body = Circle.CreateFixed(New Vector(cx + cw / 2, cy + ch / 2), r, id)
                Case Else
                    body = New Rectangle(New Vector(cx + cw * 0.1 * rng.NextDouble(), cy + ch * 0.1 * rng.NextDouble()), cw * (0.1 + 0.7 * rng.NextDouble()), ch * (0.1 + 0.7 * rng.NextDouble()), id)
            End Select
            If rng.Next(2) = 0 Then body.Color = RandomColor(rng)
            w.Add(body)
        Next
        Return w
    End Function

    Private Shared Function Awkward(rng As Random, lo As Double, hi As Double) As Double
        Return lo + (hi - lo) * rng.NextDouble()
    End Function

    Private Shared Function Velocity(rng As Random) As Double
        Select Case rng.Next(6)
            Case 0 : Return 0.0
            Case 1 : Return -0.0
            Case 2 : Return (rng.NextDouble() - 0.5) * 1.0E-300
            Case 3 : Return (rng.NextDouble() - 0.5) * 1.0E+300
            Case Else : Return (rng.NextDouble() - 0.5) * 20
        End Select
    End Function

    Private Shared Function RandomId(rng As Random) As String
        Dim pieces = {"a", "B", "ball", "7", "0", " ", "é", "雪", "\", "/", """", "'", ",", "<x>", "&amp;", "item", "type", "root", "{}", "[", vbTab, "😀"}
        Dim n = rng.Next(1, 5)
        Dim s = ""
        For i = 1 To n
            s &= pieces(rng.Next(pieces.Length))
        Next
        Return s
    End Function

    Private Shared Function RandomColor(rng As Random) As String
        Dim hex = "0123456789abcdefABCDEF"
        Dim s = "#"
        For i = 1 To 6
            s &= hex(rng.Next(hex.Length))
        Next
        Return s
    End Function

    Friend Shared Sub AssertSameScene(a As World, b As World, context As String)
        Assert.True(Same(a.Width, b.Width) AndAlso Same(a.Height, b.Height) AndAlso Same(a.Gravity, b.Gravity) AndAlso
                    Same(a.Restitution, b.Restitution) AndAlso a.Walls = b.Walls, "world settings differ: " & context)
        Assert.True(a.Bodies.Count = b.Bodies.Count, "body count differs: " & context)
        For i = 0 To a.Bodies.Count - 1
            Dim x = a.Bodies(i), y = b.Bodies(i)
            Dim where = "body " & i.ToString(CultureInfo.InvariantCulture) & ": " & context
            Assert.True(x.GetType() Is y.GetType(), "type differs, " & where)
            Assert.True(x.Id = y.Id, "id differs (" & x.Id & " / " & y.Id & "), " & where)
            Assert.True(x.Color = y.Color, "colour differs, " & where)
            Assert.True(x.IsFixed = y.IsFixed, "fixed differs, " & where)
            If TypeOf x Is Circle Then
                Dim c = DirectCast(x, Circle), d = DirectCast(y, Circle)
                Assert.True(Same(c.Position.X, d.Position.X) AndAlso Same(c.Position.Y, d.Position.Y) AndAlso Same(c.Radius, d.Radius) AndAlso
                            Same(c.Mass, d.Mass) AndAlso Same(c.Velocity.X, d.Velocity.X) AndAlso Same(c.Velocity.Y, d.Velocity.Y), "circle differs, " & where)
            ElseIf TypeOf x Is Rectangle Then
                Dim r = DirectCast(x, Rectangle), s = DirectCast(y, Rectangle)
                Assert.True(Same(r.Position.X, s.Position.X) AndAlso Same(r.Position.Y, s.Position.Y) AndAlso Same(r.Width, s.Width) AndAlso Same(r.Height, s.Height), "rectangle differs, " & where)
            ElseIf TypeOf x Is Segment Then
                Dim r = DirectCast(x, Segment), s = DirectCast(y, Segment)
                Assert.True(r.StartPoint = s.StartPoint AndAlso r.EndPoint = s.EndPoint, "segment differs, " & where)
            Else
                Dim r = DirectCast(x, Polygon), s = DirectCast(y, Polygon)
                Assert.True(r.Vertices.SequenceEqual(s.Vertices), "polygon differs, " & where)
            End If
            If Not x.IsFixed Then
                Assert.True(Same(x.Mass, y.Mass) AndAlso Same(x.Velocity.X, y.Velocity.X) AndAlso Same(x.Velocity.Y, y.Velocity.Y), "mass or velocity differs, " & where)
            End If
        Next
        Assert.True(a.Links.Count = b.Links.Count, "link count differs: " & context)
        For i = 0 To a.Links.Count - 1
            Dim x = a.Links(i), y = b.Links(i)
            Assert.True(x.Kind = y.Kind AndAlso x.Id = y.Id AndAlso Same(x.Length, y.Length) AndAlso Same(x.Stiffness, y.Stiffness) AndAlso
                        Same(x.Damping, y.Damping), "link " & i.ToString(CultureInfo.InvariantCulture) & " differs: " & context)
        Next
    End Sub

    ''' <summary>Bit for bit, so -0 and 0 differ and NaN equals itself.</summary>
    Private Shared Function Same(a As Double, b As Double) As Boolean
        Return BitConverter.DoubleToInt64Bits(a) = BitConverter.DoubleToInt64Bits(b)
    End Function
End Class
