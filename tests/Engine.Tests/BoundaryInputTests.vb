Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Inputs at the edge of what makes sense: a clear refusal or a correct run, never a crash.</summary>
Public Class BoundaryInputTests
    <Fact>
    Public Sub ACircleWiderThanAWalledContainer_IsRefused_AndTheWorldIsUnchanged()
        Dim w As New World(1, 1)
        Dim ex = Assert.Throws(Of ArgumentException)(Sub() w.Add(New Circle(New Vector(0.5, 0.5), 2.0, 1.0)))
        Assert.Contains("does not fit", ex.Message)
        Assert.Empty(w.Bodies)
    End Sub

    <Fact>
    Public Sub ShrinkingBelowTheLargestCircle_IsRefused_AndTheSizeStays()
        Dim w As New World(4, 4)
        w.Solver = SolverFactory.Create("event")
        w.Add(New Circle(New Vector(2, 2), 0.5, 1.0))
        Assert.Throws(Of ArgumentException)(Sub() w.Resize(0.9, 3))
        Assert.Equal(4.0, w.Width)
        w.Resize(1.0, 1.0) ' exactly one diameter still fits
        w.Advance(1.0)
        Dim c = w.Circles(0)
        Assert.InRange(c.Position.Y, 0.5 - 1.0E-9, 0.5 + 1.0E-9)
    End Sub

    <Theory>
    <InlineData("{""format"":""physics-scene/1"",""world"":{""width"":2,""height"":2},""bodies"":[],""x"":""a" & vbTab & "b""}")>
    <InlineData("{""format"":""physics-scene/1"",""world"":{""width"":2,""height"":2},""bodies"":[],}")>
    Public Sub MalformedJsonTheBclReaderLetsThrough_IsRejectedAsNotJson(json As String)
        Dim ex = Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(json))
        Assert.Equal("document", ex.Place)
        Assert.Contains("not valid JSON", ex.Message)
    End Sub

    <Fact>
    Public Sub DeeplyNestedBrackets_AreNotJson()
        Dim json = "{""format"":""physics-scene/1"",""world"":{""width"":2,""height"":2},""bodies"":[],""x"":" &
                   New String("["c, 10000) & New String("]"c, 10000) & "}"
        Dim ex = Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(json))
        Assert.Equal("document", ex.Place)
        Assert.Contains("depth", ex.Message)
    End Sub

    <Fact>
    Public Sub ABodyFarAwayWithWallsOff_RunsWithTheDefaultSolver()
        Dim json = "{""format"":""physics-scene/1"",""world"":{""width"":2,""height"":2,""walls"":false,""gravity"":0}," &
                   """bodies"":[{""type"":""circle"",""x"":1e12,""y"":1,""radius"":0.1,""mass"":1,""vx"":-1}," &
                   "{""type"":""circle"",""x"":1,""y"":1,""radius"":0.1,""mass"":1}]}"
        Dim w = SceneFile.Load(json)
        w.Solver = SolverFactory.Create("auto")
        w.Advance(1.0)
        Assert.Equal(1.0E+12 - 1, w.Circles(0).Position.X, 0)
    End Sub

    <Fact>
    Public Sub HugeRadiiWithWallsOff_AreCheckedWithoutOverflow()
        Dim json = "{""format"":""physics-scene/1"",""world"":{""width"":2,""height"":2,""walls"":false}," &
                   """bodies"":[{""type"":""circle"",""x"":1e308,""y"":1,""radius"":1e308,""mass"":1}]}"
        Dim w = SceneFile.Load(json)
        Assert.Single(w.Bodies)
    End Sub

    ''' <summary>A ball at speed v (m/s, along a diagonal) in a walled 10 m box with gravity and e = 0.9, next to a ball at rest.</summary>
    Private Shared Function FastBall(speed As Double) As World
        Dim w As New World(10, 10, 9.81, 0.9)
        w.Add(New Circle(New Vector(5, 5), 0.5, 1.0, New Vector(speed, -speed) / Math.Sqrt(2)) With {.Id = "fast"})
        w.Add(New Circle(New Vector(2, 2), 0.5, 1.0))
        Return w
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub ASpeedWhoseSquareOverflows_IsRefusedWithItsName_AndTheWorldIsUnchanged(solver As String)
        Dim w = TestSolvers.Run(FastBall(1.0E+300), solver)
        Dim ex = Assert.Throws(Of SpeedLimitException)(Sub() w.Advance(0.1))
        Assert.StartsWith("circle 'fast' moves at 1E+300 m/s, faster than the 1E+150 m/s", ex.Message)
        Assert.Same(w.Circles(0), ex.Body)
        Assert.Equal(0.0, w.Time)
        Assert.Equal(New Vector(5, 5), w.Circles(0).Position)
        Assert.Equal(New Vector(2, 2), w.Circles(1).Position)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub JustBelowTheSpeedLimit_EverySolverKeepsAFiniteStateInsideTheBox(solver As String)
        ' Past the limit the stepping solvers produce NaN and the event solver stops the ball dead.
        Dim w = TestSolvers.Run(FastBall(0.99 * World.MaxSpeed), solver)
        w.Advance(0.1)
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite, $"{solver}: circle {c.Id} at {c.Position}, {c.Velocity}")
            Assert.InRange(c.Position.X, 0.5 - 1.0E-9, 9.5 + 1.0E-9)
            Assert.InRange(c.Position.Y, 0.5 - 1.0E-9, 9.5 + 1.0E-9)
        Next
        ' Still fast: it bounced, losing a factor e of the speed across the wall at each bounce (about
        ' 1 000 m/s left after 0.1 s, by the bounces' geometric series), and did not stop dead.
        Assert.True(w.Circles(0).Velocity.Length > 100, $"{solver}: {w.Circles(0).Velocity}")
    End Sub
End Class

''' <summary>The event solver with nothing, or only one thing, to move.</summary>
Public Class EventSolverEmptyWorldTests
    <Theory>
    <InlineData(0)>
    <InlineData(1)>
    <InlineData(2)>
    Public Sub AWorldWithFewMovableCircles_Advances(count As Integer)
        Dim w As New World(4, 4, 9.81, 0.9)
        w.Add(New Rectangle(New Vector(1, 0), 1, 1))
        w.Add(Circle.CreateFixed(New Vector(3, 1), 0.2))
        For i = 1 To count
            w.Add(New Circle(New Vector(i, 3), 0.1, 1.0))
        Next
        w.Solver = SolverFactory.Create("event")
        w.Advance(0.5)
        w.Resize(3.5, 3.5)
        w.Advance(0.5)
        Assert.Equal(1.0, w.Time, 12)
        Assert.Equal(count, w.Circles.Count - 1)
    End Sub
End Class
