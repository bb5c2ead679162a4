Option Strict On

Imports Xunit

''' <summary>
''' <see cref="TieLock"/>: which pairs of ties in line hold their body where it is, from the second-order reasoning
''' (a rod asks z = s²/(2L), a string z ≥ s²/(2L), towards its anchor), and the row it adds.
''' </summary>
Public Class TieLockTests
    <Theory>
    <InlineData(True, 1.0, True, 0.5, True, True)>     ' two rods of different lengths, same side: the circles touch inside
    <InlineData(True, 1.0, True, 1.0, True, False)>    ' the same rod twice: one circle
    <InlineData(True, 1.0, False, 0.5, True, True)>    ' rod the longer, string the shorter: on the big circle, inside the small
    <InlineData(True, 0.5, False, 1.0, True, False)>   ' rod the shorter: it swings on the rod, the string goes slack
    <InlineData(False, 0.5, True, 1.0, True, True)>    ' the same two, given the other way round
    <InlineData(False, 0.5, False, 1.0, True, False)>  ' two strings, same side: it swings on the shorter
    <InlineData(True, 1.0, True, 1.0, False, True)>    ' anchors on opposite sides: always held
    <InlineData(False, 1.0, False, 2.0, False, True)>
    <InlineData(True, 1.0, False, 2.0, False, True)>
    Public Sub HoldsWhereNoSmallMoveAcrossMeetsBoth(rod1 As Boolean, length1 As Double, rod2 As Boolean, length2 As Double, sameSide As Boolean, expected As Boolean)
        Assert.Equal(expected, TieLock.Holds(rod1, length1, rod2, length2, sameSide))
    End Sub

    ''' <summary>The rule checked against the geometry: a small move across, kept on each rod, lands off the other.</summary>
    <Fact>
    Public Sub TwoRodsOfDifferentLengthsInLine_LeaveNoRoomToMove()
        ' Body at the origin, anchors straight above at 0.9 m and 0.15 m: move 10⁻³ m across and onto the first rod's circle.
        Dim s = 0.001
        Dim z = 0.9 - Math.Sqrt(0.9 * 0.9 - s * s)
        Dim toSecond = Math.Sqrt(s * s + (0.15 - z) * (0.15 - z))
        Assert.True(toSecond - 0.15 > 0.000001, $"the second rod stretched by only {toSecond - 0.15} m")
        Assert.True(TieLock.Holds(True, 0.9, True, 0.15, True))
    End Sub

    <Fact>
    Public Sub TwoRodsInLine_AddOneRowAcrossThem_AtTheBodyNow()
        Dim state = {2.0, 1.0, 0.0, 0.0}
        Dim rows = {Constraint.Tie(0, -1, New Vector(2, 1.9), 0.9, holds:=True),
                    Constraint.Tie(0, -1, New Vector(2, 1.15), 0.15, holds:=True)}
        Dim locks = TieLock.Find(rows, state)
        Dim lock = Assert.Single(locks)
        Assert.True(lock.IsLock)
        Assert.True(lock.Holds)
        Assert.Equal(0, lock.A)
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        lock.Measure(state, u, value, rate, curvature)
        Assert.Equal(0.0, u.Y, 15)
        Assert.Equal(1.0, Math.Abs(u.X), 15)
        Assert.Equal(0.0, value, 15)
        ' Moving across changes it at once: the row the two rods cannot give.
        Dim moved = {2.001, 1.0, 0.5, 0.0}
        lock.Measure(moved, u, value, rate, curvature)
        Assert.Equal(0.001, Math.Abs(value), 12)
        Assert.Equal(0.5, Math.Abs(rate), 12)
    End Sub

    <Fact>
    Public Sub TiesNotInLine_OrTheSameCircle_OrOnDifferentBodies_AddNone()
        Dim state = {2.0, 1.0, 0.0, 0.0, 5.0, 1.0, 0.0, 0.0}
        ' Not in line: two rods to points up-left and up-right (already independent rows).
        Assert.Empty(TieLock.Find({Constraint.Tie(0, -1, New Vector(1.5, 1.5), Math.Sqrt(0.5), True),
                                   Constraint.Tie(0, -1, New Vector(2.5, 1.5), Math.Sqrt(0.5), True)}, state))
        ' The same rod twice.
        Assert.Empty(TieLock.Find({Constraint.Tie(0, -1, New Vector(2, 1.9), 0.9, True),
                                   Constraint.Tie(0, -1, New Vector(2, 1.9), 0.9, True)}, state))
        ' A rod shorter than the string in line with it.
        Assert.Empty(TieLock.Find({Constraint.Tie(0, -1, New Vector(2, 1.15), 0.15, True),
                                   Constraint.Tie(0, -1, New Vector(2, 1.9), 0.9, False)}, state))
        ' In line, but on two bodies.
        Assert.Empty(TieLock.Find({Constraint.Tie(0, -1, New Vector(2, 1.9), 0.9, True),
                                   Constraint.Tie(1, -1, New Vector(5, 1.15), 0.15, True)}, state))
        ' Between two bodies, not to fixed points.
        Assert.Empty(TieLock.Find({Constraint.Tie(0, 1, Vector.Zero, 3, True),
                                   Constraint.Tie(0, -1, New Vector(2.5, 1), 0.5, True)}, state))
    End Sub
End Class
