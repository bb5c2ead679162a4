Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The grid broad phase against brute force: every pair that touches is found, in scenes whose sizes
''' differ by factors of a thousand (where the large bodies are set apart), and box queries return
''' exactly the items whose boxes meet the box, in order.
''' </summary>
Public Class BroadPhaseTests
    Private Shared ReadOnly PairNames As String() = {"circle-rectangle", "circle-polygon", "rectangle-polygon"}
    Private Shared ReadOnly FiniteItems As Integer() = {0, 2}

    ''' <summary>Tiny balls, some medium boxes and polygons, and a few bodies a hundred to a thousand times larger.</summary>
    Private Shared Function Bodies(seed As Integer, count As Integer, Optional width As Double = 4, Optional height As Double = 3, Optional evenSpread As Boolean = False) As List(Of Shape)
        Dim rng As New Random(seed)
        Dim list As New List(Of Shape)
        For i = 0 To count - 1
            Dim p = New Vector(width * rng.NextDouble(), height * rng.NextDouble())
            Dim pick = rng.NextDouble()
            Dim size = If(pick < 0.02, 0.3 + 0.7 * rng.NextDouble(), If(pick < 0.2, 0.01 + 0.03 * rng.NextDouble(), 0.001 + 0.003 * rng.NextDouble()))
            If evenSpread Then size = 0.05 * Math.Pow(10, pick) ' 5 to 50 cm, log-uniform
            Select Case rng.Next(3)
                Case 0
                    list.Add(New Circle(p, size, 1.0))
                Case 1
                    list.Add(Rectangle.CreateMovable(p, size * (0.2 + rng.NextDouble()), size * (0.2 + rng.NextDouble()), 1.0))
                Case Else
                    list.Add(New Polygon({p, p + New Vector(size, 0), p + New Vector(0.3 * size, size)}, 1.0))
            End Select
        Next
        Return list
    End Function

    ''' <summary>Whether the broad phase must keep the pair: overlapping or touching (its margin may add more).</summary>
    Private Shared Function Touch(a As Shape, b As Shape) As Boolean
        Return Collider.OutlineOutline(a.Outline, a.Position, b.Outline, b.Position).Depth >= 0
    End Function

    <Theory>
    <InlineData(1, 400, False)>
    <InlineData(2, 1500, False)>
    <InlineData(3, 40, True)>
    Public Sub FindOverlaps_FindsEveryTouchingPair_OnceEach_WhateverTheSizes(seed As Integer, count As Integer, evenSpread As Boolean)
        ' Crowds of tiny bodies with a few large ones, which are set apart; and sizes spread evenly over a
        ' factor of ten, where cells as wide as the largest are not crowded and serve every body.
        Dim list = Bodies(seed, count, 3, 2, evenSpread)
        Dim grid As New BoundsGrid()
        grid.Reset(list.Count)
        For i = 0 To list.Count - 1
            Dim b = list(i)
            grid.SetItem(i, 0.5 * (b.BoundsMin + b.BoundsMax), 0.5 * (b.BoundsMax.X - b.BoundsMin.X), 0.5 * (b.BoundsMax.Y - b.BoundsMin.Y))
        Next
        grid.Build(BroadPhase.Margin)
        Assert.Equal(Not evenSpread, grid.LargeCount > 0)
        Dim found As New List(Of (A As Integer, B As Integer))
        Dim phase As New BroadPhase()
        phase.FindOverlaps(list, found)
        Dim seen As New HashSet(Of (Integer, Integer))
        For Each p In found
            Assert.True(seen.Add((Math.Min(p.A, p.B), Math.Max(p.A, p.B))), $"pair {p} found twice")
        Next
        Dim touching = 0
        For i = 0 To list.Count - 1
            For j = i + 1 To list.Count - 1
                If Touch(list(i), list(j)) Then
                    touching += 1
                    Assert.True(seen.Contains((i, j)), $"pair ({i}, {j}) of a {list(i).KindName} and a {list(j).KindName} was missed")
                End If
            Next
        Next
        Assert.True(touching > count \ 20, $"only {touching} touching pairs: the scene tests nothing")
    End Sub

    <Fact>
    Public Sub FindOverlaps_NamesEachPairCircleBeforeRectangleBeforePolygon()
        Dim list As New List(Of Shape) From {
            New Polygon({New Vector(0, 0), New Vector(1, 0), New Vector(0, 1)}, 1.0),
            Rectangle.CreateMovable(New Vector(0.5, 0), 1, 1, 1.0),
            New Circle(New Vector(0.2, 0.2), 0.5, 1.0)}
        Dim found As New List(Of (A As Integer, B As Integer))
        Call New BroadPhase().FindOverlaps(list, found)
        Assert.Equal(3, found.Count)
        For Each p In found
            Dim name = list(p.A).KindName & "-" & list(p.B).KindName
            Assert.Contains(name, PairNames)
        Next
    End Sub

    <Theory>
    <InlineData(4, 800)>
    <InlineData(5, 30)>
    Public Sub GridQuery_ReturnsExactlyTheItemsWhoseBoxesMeet_InOrder(seed As Integer, count As Integer)
        Dim list = Bodies(seed, count)
        Dim grid As New BoundsGrid()
        grid.Reset(list.Count)
        For i = 0 To list.Count - 1
            Dim b = list(i)
            grid.SetItem(i, 0.5 * (b.BoundsMin + b.BoundsMax), 0.5 * (b.BoundsMax.X - b.BoundsMin.X), 0.5 * (b.BoundsMax.Y - b.BoundsMin.Y))
        Next
        grid.Build(0)
        Assert.True(count < 100 OrElse grid.LargeCount > 0, "the crowded scene should set its large bodies apart")
        Dim rng As New Random(seed)
        Dim result As New List(Of Integer)
        For q = 1 To 300
            Dim lo = New Vector(5 * rng.NextDouble() - 0.5, 4 * rng.NextDouble() - 0.5)
            Dim hi = lo + New Vector(If(q Mod 10 = 0, 3, 0.05) * rng.NextDouble(), If(q Mod 10 = 0, 3, 0.05) * rng.NextDouble())
            grid.Query(lo, hi, result)
            Dim expected As New List(Of Integer)
            For i = 0 To list.Count - 1
                Dim cx = grid.CentreX(i), cy = grid.CentreY(i), hx = grid.HalfWidth(i), hy = grid.HalfHeight(i)
                If cx + hx >= lo.X AndAlso cx - hx <= hi.X AndAlso cy + hy >= lo.Y AndAlso cy - hy <= hi.Y Then expected.Add(i)
            Next
            Assert.Equal(expected, result)
        Next
    End Sub

    <Fact>
    Public Sub GridQuery_WithANonFiniteBox_ReturnsEveryFiniteItem_AndItemsThatAreNotFiniteAreLeftOut()
        Dim grid As New BoundsGrid()
        grid.Reset(3)
        grid.SetItem(0, New Vector(0, 0), 1, 1)
        grid.SetItem(1, New Vector(Double.NaN, 0), 1, 1)
        grid.SetItem(2, New Vector(5, 5), 1, 1)
        grid.Build(0)
        Dim result As New List(Of Integer)
        grid.Query(New Vector(Double.NegativeInfinity, 0), New Vector(0, 0), result)
        Assert.Equal(FiniteItems, result)
        grid.Query(New Vector(-10, -10), New Vector(10, 10), result)
        Assert.Equal(FiniteItems, result)
    End Sub
End Class
