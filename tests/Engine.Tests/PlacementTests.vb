Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Where a body may go: overlaps, sweeps that never jump over a body, sliding, the nearest free place.</summary>
Public Class PlacementTests
    Private Shared Function Box() As World
        Dim w As New World(10, 6, 9.81, 1.0)
        w.Add(New Rectangle(New Vector(4, 0), 2, 2, "table"))
        w.Add(Circle.CreateFixed(New Vector(8, 4), 0.5, "peg"))
        Return w
    End Function

    <Fact>
    Public Sub FirstOverlap_FindsWhatABodyWouldEnter_AndIgnoresFixedPairs()
        Dim w = Box()
        Dim ball As New Circle(New Vector(5, 1), 0.3, 1.0)
        Assert.Equal("table", Placement.FirstOverlap(w, ball, Vector.Zero).Id)
        Assert.Null(Placement.FirstOverlap(w, ball, New Vector(-2, 2)))
        Assert.Equal("peg", Placement.FirstOverlap(w, ball, New Vector(2.5, 3)).Id)
        ' A fixed ball may sit on the table: fixed bodies never collide with each other.
        Assert.Null(Placement.FirstOverlap(w, Circle.CreateFixed(New Vector(5, 1), 0.3), Vector.Zero))
    End Sub

    <Fact>
    Public Sub Touching_IsFree_OverlappingByMoreThanTheTolerance_IsNot()
        Dim w = Box()
        Dim ball As New Circle(New Vector(3.7, 1), 0.3, 1.0)
        Assert.True(Placement.IsFree(w, ball, Vector.Zero))
        Assert.False(Placement.IsFree(w, ball, New Vector(0.000001, 0)))
        Assert.Equal(0.000001, Placement.OverlapDepth(ball, New Vector(0.000001, 0), w.Find("table")), 9)
    End Sub

    <Fact>
    Public Sub IsInside_HoldsMovableBodiesToAWalledContainer_Only()
        Dim w = Box()
        Dim ball As New Circle(New Vector(1, 1), 0.5, 1.0)
        Assert.True(Placement.IsInside(w, ball, Vector.Zero))
        Assert.False(Placement.IsInside(w, ball, New Vector(-0.6, 0)))
        Assert.True(Placement.IsInside(w, Circle.CreateFixed(New Vector(-3, 1), 0.5), Vector.Zero))
        w.Walls = False
        Assert.True(Placement.IsInside(w, ball, New Vector(-30, 0)))
    End Sub

    <Fact>
    Public Sub Sweep_StopsAtTheFirstContact_HoweverLongTheMove()
        Dim w As New World(100, 6, 0.0, 1.0)
        w.Add(New Circle(New Vector(50, 3), 0.2, 1.0, id:="thin"))
        Dim carried As New Circle(New Vector(10, 3), 0.3, 1.0)
        w.Add(carried)
        ' 80 m in one go would jump straight over the thin ball: the sweep solves for the contact.
        Dim s = Placement.SweepTo(w, carried, New Vector(80, 0))
        Assert.Equal("thin", s.Blocker.Id)
        Assert.Equal((50 - 0.5 - 10) / 80.0, s.Fraction, 12)
        Assert.Equal(-1.0, s.Normal.X, 12)
    End Sub

    <Fact>
    Public Sub Sweep_AgainstABox_StopsAtItsFace_AndAtItsRoundedCorner()
        Dim w = Box()
        Dim ball As New Circle(New Vector(1, 1), 0.5, 1.0)
        Dim face = Placement.SweepTo(w, ball, New Vector(6, 0))
        Assert.Equal("table", face.Blocker.Id)
        Assert.Equal(2.5 / 6, face.Fraction, 12)
        ' Skimming the top-left corner (4, 2) on a line 0.3 m above it: touches where |(x, 2.3) − (4, 2)| = 0.5.
        Dim high As New Circle(New Vector(1, 2.3), 0.5, 1.0)
        Dim corner = Placement.SweepTo(w, high, New Vector(6, 0))
        Assert.Equal((4 - 0.4 - 1) / 6, corner.Fraction, 12)
    End Sub

    <Fact>
    Public Sub Sweep_OnlyCountsTheBodiesAskedFor()
        Dim w As New World(10, 6, 0.0, 1.0)
        w.Add(New Circle(New Vector(5, 3), 0.3, 1.0, id:="other"))
        w.Add(Circle.CreateFixed(New Vector(8, 3), 0.3, "peg"))
        Dim carried As New Circle(New Vector(2, 3), 0.3, 1.0)
        Dim s = Placement.SweepTo(w, carried, New Vector(7, 0), Function(b) b.IsFixed)
        Assert.Equal("peg", s.Blocker.Id)
    End Sub

    <Fact>
    Public Sub Sweep_KeepsAMovableBodyInsideTheWalls()
        Dim w = Box()
        Dim ball As New Circle(New Vector(1, 3), 0.5, 1.0)
        Dim s = Placement.SweepTo(w, ball, New Vector(0, 10))
        Assert.True(s.ByWall)
        Assert.Equal(2.5 / 10, s.Fraction, 12)
        Assert.Equal(-1.0, s.Normal.Y, 12)
    End Sub

    <Fact>
    Public Sub Sweep_FromContact_AllowsAwayAndAlong_NotInto()
        Dim w = Box()
        Dim ball As New Circle(New Vector(3.5, 1), 0.5, 1.0) ' touching the table's left face
        Assert.Equal(0.0, Placement.SweepTo(w, ball, New Vector(1, 0)).Fraction)
        Assert.Equal(1.0, Placement.SweepTo(w, ball, New Vector(-1, 0)).Fraction)
        Assert.Equal(1.0, Placement.SweepTo(w, ball, New Vector(0, 0.4)).Fraction)
    End Sub

    <Fact>
    Public Sub Slide_FollowsTheFaceInsteadOfStopping()
        Dim w = Box()
        Dim ball As New Circle(New Vector(3, 1), 0.5, 1.0)
        ' Aimed into the table and up: it goes to the face, then up along it.
        Dim reached = Placement.SlideTo(w, ball, New Vector(2, 2))
        Assert.Equal(0.5, reached.X, 9)
        Assert.Equal(2.0, reached.Y, 9)
        Assert.True(Placement.IsFree(w, ball, reached))
    End Sub

    <Fact>
    Public Sub RectangleCarried_StopsAtAMovableBall_ButPassesOverAFixedOne()
        Dim w As New World(10, 6, 0.0, 1.0)
        w.Add(Circle.CreateFixed(New Vector(4, 3), 0.3, "peg"))
        w.Add(New Circle(New Vector(7, 3), 0.3, 1.0, id:="ball"))
        Dim table As New Rectangle(New Vector(0, 2.5), 1, 1, "table")
        w.Add(table)
        Dim s = Placement.SweepTo(w, table, New Vector(8, 0))
        Assert.Equal("ball", s.Blocker.Id)
        Assert.Equal((7 - 0.3 - 1) / 8.0, s.Fraction, 12)
    End Sub

    <Fact>
    Public Sub NearestFree_MovesABallOutOfABoxToTheNearestSide()
        Dim w = Box()
        Dim ball As New Circle(New Vector(5, 1.8), 0.3, 1.0) ' in the table, near its top
        Dim place = Placement.NearestFree(w, ball, Vector.Zero, 2.0)
        Assert.True(place.HasValue)
        Assert.True(Placement.IsFree(w, ball, place.Value))
        Dim centre = ball.Position + place.Value
        Assert.True(centre.Y >= 2.3 - 0.05 AndAlso centre.Y <= 2.3 + 0.1, $"on top of the table, not at {centre}")
        Assert.Equal(5.0, centre.X, 1)
    End Sub

    <Fact>
    Public Sub NearestFree_BringsAMovableBallInsideTheWalls_AndSaysWhenThereIsNoRoom()
        Dim w As New World(2, 2, 9.81, 1.0)
        Dim ball As New Circle(New Vector(-1, 1), 0.3, 1.0)
        Dim place = Placement.NearestFree(w, ball, Vector.Zero, 1.0)
        Assert.Equal(0.3, (ball.Position + place.Value).X, 9)
        w.Add(New Rectangle(New Vector(-1, -1), 4, 4, "floor"))
        Assert.Null(Placement.NearestFree(w, ball, Vector.Zero, 1.0))
    End Sub

    <Fact>
    Public Sub FindProblem_NamesTheOverlapAScenesFileWouldRefuse()
        Dim w = Box()
        Assert.Null(Placement.FindProblem(w))
        w.Add(New Circle(New Vector(5, 1.5), 0.3, 1.0, id:="stuck"))
        Dim problem = Placement.FindProblem(w)
        Assert.Contains("'stuck' overlaps 'table'", problem, StringComparison.Ordinal)
        Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(SceneFile.Save(w)))
    End Sub

    <Fact>
    Public Sub EveryKindOfBody_IsHandledAlike_SegmentsPolygonsAndMovableBoxes()
        Dim w As New World(10, 6, 0.0, 1.0)
        w.Add(New Segment(New Vector(5, 0), New Vector(5, 4), "wall"))
        w.Add(Polygon.CreateFixed({New Vector(7, 4), New Vector(9, 4), New Vector(8, 5.5)}, "roof"))
        Dim ball As New Circle(New Vector(2, 2), 0.5, 1.0)
        w.Add(ball)
        ' The ball stops against the segment (x = 5), a radius short of it.
        Dim s = Placement.SweepTo(w, ball, New Vector(6, 0))
        Assert.Equal("wall", s.Blocker.Id)
        Assert.Equal((5 - 0.5 - 2) / 6.0, s.Fraction, 9)
        Dim over As New Circle(New Vector(8, 2), 0.5, 1.0)
        Dim up = Placement.SweepTo(w, over, New Vector(0, 3))
        Assert.Equal("roof", up.Blocker.Id)
        Assert.Equal(1.5 / 3.0, up.Fraction, 9)
        ' A movable box may not overlap the ball, and keeps to the walls.
        Dim box = Rectangle.CreateMovable(New Vector(1.8, 1.8), 1, 1, 2.0)
        Assert.Same(ball, Placement.FirstOverlap(w, box, Vector.Zero))
        Assert.False(Placement.IsInside(w, box, New Vector(-2, 0)))
        Dim place = Placement.NearestFree(w, box, Vector.Zero, 3.0)
        Assert.True(place.HasValue)
        Assert.True(Placement.IsFree(w, box, place.Value))
    End Sub

    <Fact>
    Public Sub AWorldKeptFree_SavesToAFileThatOpens()
        Dim w = Box()
        Dim rng As New Random(3)
        For k = 1 To 60
            Dim ball As New Circle(New Vector(rng.NextDouble() * 10, rng.NextDouble() * 6), 0.1 + 0.3 * rng.NextDouble(), 1.0)
            Dim place = Placement.NearestFree(w, ball, Vector.Zero, 3.0)
            If place.HasValue Then
                ball.Position += place.Value
                w.Add(ball)
            End If
        Next
        Assert.True(w.Circles.Count > 40)
        Assert.Null(Placement.FindProblem(w))
        Dim copy = SceneFile.Load(SceneFile.Save(w))
        Assert.Equal(w.Bodies.Count, copy.Bodies.Count)
    End Sub
End Class
