Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports Xunit

''' <summary>Two runs' collision logs and end states compare to the bit, and the first difference is named.</summary>
Public Class CollisionLogTests
    Private Shared ReadOnly A As New Circle(New Vector(1, 1), 0.1, 1.0, id:="a")
    Private Shared ReadOnly B As New Circle(New Vector(2, 1), 0.1, 1.0, id:="b")

    Private Shared Function Hit(t As Double, Optional vx As Double = 1.0) As CollisionRecord
        Return New CollisionRecord(t, A, B, WallSide.Left, CollisionKind.CircleCircle, New Vector(vx, 0), New Vector(0, 0), New Vector(0, 0), New Vector(vx, 0))
    End Function

    Private Shared Function Wall(t As Double, side As WallSide) As CollisionRecord
        Return New CollisionRecord(t, A, Nothing, side, CollisionKind.CircleWall, New Vector(-1, 0), New Vector(1, 0), Vector.Zero, Vector.Zero)
    End Function

    Private Shared Function Log(limit As Integer, ParamArray records As CollisionRecord()) As CollisionLog
        Dim l As New CollisionLog(limit)
        For Each r In records
            l.Add(r)
        Next
        Return l
    End Function

    Private Shared Function Compare(x As CollisionLog, y As CollisionLog) As String
        Dim t = Double.NaN
        Return CollisionLog.FirstDifference(x, y, "first", "second", t)
    End Function

    <Fact>
    Public Sub TheSameCollisions_AreNoDifference()
        Assert.Null(Compare(Log(10, Hit(0.1), Wall(0.2, WallSide.Left)), Log(10, Hit(0.1), Wall(0.2, WallSide.Left))))
        Assert.Null(Compare(Log(1, Hit(0.1), Hit(0.3)), Log(1, Hit(0.1), Hit(0.3))))
    End Sub

    <Fact>
    Public Sub ATimeOneBitLater_IsADifference_AtThatCollision()
        Dim later = BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(0.2) + 1)
        Dim t = Double.NaN
        Dim message = CollisionLog.FirstDifference(Log(10, Hit(0.1), Hit(0.2)), Log(10, Hit(0.1), Hit(later)), "first", "second", t)
        Assert.StartsWith("collision #2 differs", message, StringComparison.Ordinal)
        Assert.Equal(0.2, t)
    End Sub

    <Fact>
    Public Sub AVelocityOneBitOff_OrAnotherWall_IsADifference()
        Dim off = BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(1.0) + 1)
        Assert.NotNull(Compare(Log(10, Hit(0.1)), Log(10, Hit(0.1, off))))
        Assert.NotNull(Compare(Log(10, Wall(0.1, WallSide.Left)), Log(10, Wall(0.1, WallSide.Right))))
    End Sub

    <Fact>
    Public Sub AnExtraCollision_IsNamed()
        Dim message = Compare(Log(10, Hit(0.1)), Log(10, Hit(0.1), Wall(0.4, WallSide.Top)))
        Assert.Contains("#2 is only in second", message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ADifferenceBeyondTheKeptCollisions_IsStillFound()
        Dim message = Compare(Log(2, Hit(0.1), Hit(0.2), Hit(0.3), Hit(0.4)), Log(2, Hit(0.1), Hit(0.2), Hit(0.3), Hit(0.5)))
        Assert.Contains("the later ones differ", message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub EndStates_CompareToTheBit()
        Dim w1 As New World(4, 3)
        Dim w2 As New World(4, 3)
        w1.Add(New Circle(New Vector(1, 1), 0.1, 1.0, New Vector(0.5, 0), "a"))
        w2.Add(New Circle(New Vector(1, 1), 0.1, 1.0, New Vector(0.5, 0), "a"))
        Assert.Null(FinalState.FirstDifference(New FinalState(w1), New FinalState(w2), "first", "second"))
        w2.Circles(0).Velocity = New Vector(BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(0.5) + 1), 0)
        Assert.StartsWith("a ends at", FinalState.FirstDifference(New FinalState(w1), New FinalState(w2), "first", "second"), StringComparison.Ordinal)
    End Sub
End Class
