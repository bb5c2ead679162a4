Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>The grid overlap check finds exactly what checking every pair finds, and copes with 100 000 circles.</summary>
Public Class OverlapCheckTests
    <Fact>
    Public Sub Grid_AgreesWithEveryPair_OnRandomScenes()
        For seed = 1 To 400
            Dim rng As New Random(seed)
            Dim bodies As New List(Of BodySpec)
            Dim n = rng.Next(2, 40)
            For i = 0 To n - 1
                Dim b As New BodySpec With {.Index = i, .X = rng.NextDouble() * 10 - 2, .Y = rng.NextDouble() * 10 - 2}
                Select Case rng.Next(12)
                    Case 0 ' a large rectangle
                        b.Kind = ShapeKind.Rectangle
                        b.IsFixed = True
                        b.Width = rng.NextDouble() * 12
                        b.Height = rng.NextDouble() * 0.5 + 0.01
                    Case 1 ' a small box, fixed or movable
                        b.Kind = ShapeKind.Rectangle
                        b.IsFixed = rng.Next(2) = 0
                        b.Width = rng.NextDouble() * 0.3 + 0.01
                        b.Height = rng.NextDouble() * 0.3 + 0.01
                    Case 2 ' a huge fixed circle
                        b.IsFixed = True
                        b.Radius = rng.NextDouble() * 3
                    Case 3 ' a segment
                        b.Kind = ShapeKind.Segment
                        b.IsFixed = True
                        b.X2 = b.X + rng.NextDouble() * 4 - 2
                        b.Y2 = b.Y + rng.NextDouble() * 4 - 2
                    Case 4 ' a triangle, fixed or movable
                        b.Kind = ShapeKind.Polygon
                        b.IsFixed = rng.Next(2) = 0
                        b.Vertices = {New Vector(b.X, b.Y), New Vector(b.X + 0.3, b.Y), New Vector(b.X, b.Y + 0.2 + 0.3 * rng.NextDouble())}
                    Case Else
                        b.IsFixed = rng.Next(4) = 0
                        b.Radius = rng.NextDouble() * 0.2 + 0.01
                End Select
                Shaped(b)
                bodies.Add(b)
            Next
            Dim expected = BruteForce(bodies)
            Dim actual As String = Nothing
            Try
                OverlapCheck.Check(bodies)
            Catch ex As SceneFormatException
                actual = ex.Message
            End Try
            Assert.True(expected = actual, "seed " & seed.ToString(CultureInfo.InvariantCulture) & ": expected " & If(expected, "no overlap") & ", got " & If(actual, "no overlap"))
        Next
    End Sub

    ''' <summary>Gives a spec its outline and reference point, as the reader does.</summary>
    Private Shared Sub Shaped(b As BodySpec)
        Select Case b.Kind
            Case ShapeKind.Circle
                b.Outline = Outline.Point(b.Radius)
                b.Position = New Vector(b.X, b.Y)
            Case ShapeKind.Rectangle
                b.Outline = Outline.Box(b.Width, b.Height)
                b.Position = New Vector(b.X, b.Y)
            Case ShapeKind.Segment
                b.Outline = Outline.Segment(Vector.Zero, New Vector(b.X2 - b.X, b.Y2 - b.Y))
                b.Position = New Vector(b.X, b.Y)
            Case Else
                Dim core = Outline.Polygon(b.Vertices)
                b.Position = core.Centroid
                b.Outline = core.Translated(-core.Centroid)
        End Select
    End Sub

    ''' <summary>The first body (in order) that overlaps an earlier one, and the earliest such partner.</summary>
    Private Shared Function BruteForce(bodies As List(Of BodySpec)) As String
        For j = 0 To bodies.Count - 1
            For i = 0 To j - 1
                Dim d = OverlapCheck.OverlapDepth(bodies(i), bodies(j))
                If d > OverlapCheck.Tolerance Then
                    Return "bodies[" & j.ToString(CultureInfo.InvariantCulture) & "]: overlaps bodies[" & i.ToString(CultureInfo.InvariantCulture) &
                           "] by " & d.ToString("G6", CultureInfo.InvariantCulture) & " m"
                End If
            Next
        Next
        Return Nothing
    End Function

    <Fact>
    Public Sub OverlapDepth_MatchesHandWorkedCases()
        Dim box = Spec(ShapeKind.Rectangle, 0, 0, width:=2, height:=1)
        ' centre above the top face, 0.05 m into it
        Assert.Equal(0.05, OverlapCheck.OverlapDepth(Spec(ShapeKind.Circle, 1, 1.05, radius:=0.1), box), 12)
        ' centre inside, 0.2 m below the top face: it must go up 0.2 m and a radius more
        Assert.Equal(0.3, OverlapCheck.OverlapDepth(Spec(ShapeKind.Circle, 1, 0.8, radius:=0.1), box), 12)
        ' near a corner: distance to the corner is 0.05·√2
        Assert.Equal(0.1 - 0.05 * Math.Sqrt(2), OverlapCheck.OverlapDepth(Spec(ShapeKind.Circle, 2.05, 1.05, radius:=0.1), box), 12)
        ' touching the right face
        Assert.Equal(0.0, OverlapCheck.OverlapDepth(Spec(ShapeKind.Circle, 2.1, 0.5, radius:=0.1), box), 12)
        ' a movable box sunk 0.1 m into the fixed one's top
        Assert.Equal(0.1, OverlapCheck.OverlapDepth(Spec(ShapeKind.Rectangle, 0.5, 0.9, width:=0.5, height:=0.5, fixedBody:=False), box), 12)
        ' two fixed bodies never collide, so they may overlap
        Assert.Equal(0.0, OverlapCheck.OverlapDepth(Spec(ShapeKind.Circle, 1, 0.5, radius:=0.3, fixedBody:=True), box), 12)
    End Sub

    Private Shared Function Spec(kind As ShapeKind, x As Double, y As Double, Optional radius As Double = 0, Optional width As Double = 0,
                                 Optional height As Double = 0, Optional fixedBody As Boolean? = Nothing) As BodySpec
        Dim b As New BodySpec With {.Kind = kind, .X = x, .Y = y, .Radius = radius, .Width = width, .Height = height,
                                    .IsFixed = If(fixedBody, kind = ShapeKind.Rectangle)}
        Shaped(b)
        Return b
    End Function

    <Fact>
    Public Sub AHundredThousandCircles_Load_AndAnOverlapAtTheEndIsFound()
        Assert.Equal(100000, SceneFile.Load(Gas(100000, lastOverlapsFirst:=False)).Circles.Count)
        Dim ex = Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(Gas(100000, lastOverlapsFirst:=True)))
        Assert.Equal("bodies[99999]: overlaps bodies[0] by 0.01 m", ex.Message)
    End Sub

    ''' <summary>N circles (r = 1 cm) apart on a 2.5 cm grid; optionally the last one half over the first.</summary>
    Private Shared Function Gas(count As Integer, lastOverlapsFirst As Boolean) As String
        Dim perRow = CInt(Math.Ceiling(Math.Sqrt(count)))
        Dim side = (perRow + 1) * 0.025
        Dim sb As New Text.StringBuilder()
        sb.Append("{""format"":""physics-scene/1"",""world"":{""width"":").Append(side.ToString("R", CultureInfo.InvariantCulture))
        sb.Append(",""height"":").Append(side.ToString("R", CultureInfo.InvariantCulture)).Append(",""gravity"":0},""bodies"":[")
        For i = 0 To count - 1
            Dim x = 0.025 * (i Mod perRow + 1), y = 0.025 * (i \ perRow + 1)
            If lastOverlapsFirst AndAlso i = count - 1 Then
                x = 0.035
                y = 0.025
            End If
            If i > 0 Then sb.Append(","c)
            sb.Append("{""id"":""g").Append(i.ToString(CultureInfo.InvariantCulture)).Append(""",""type"":""circle"",""x"":").Append(x.ToString("R", CultureInfo.InvariantCulture))
            sb.Append(",""y"":").Append(y.ToString("R", CultureInfo.InvariantCulture)).Append(",""radius"":0.01,""mass"":1,""vx"":0.5,""vy"":-0.25}")
        Next
        Return sb.Append("]}").ToString()
    End Function
End Class
