Option Strict On

#If NET Then
Imports System.Runtime.CompilerServices
Imports System.Runtime.Intrinsics

''' <summary>
''' The published motion of the (up to four) bodies in one grid cell's lanes, field by field: lane k
''' of every vector belongs to the cell's k-th body. At time T0 (s) it is at (Px, Py) m with velocity
''' (Vx, Vy) m/s and vertical acceleration Ay m/s² (NaN unless its acceleration is vertical and its
''' path a parabola, so that equal values mean equal accelerations and a straight relative path);
''' radius R m; its next collision-type event at ColTime (s). The vectorised pair test loads each
''' field of a whole cell at once.
''' </summary>
Friend Structure LaneBlock
    Friend T0 As Vector256(Of Double)
    Friend Px As Vector256(Of Double)
    Friend Py As Vector256(Of Double)
    Friend Vx As Vector256(Of Double)
    Friend Vy As Vector256(Of Double)
    Friend Ay As Vector256(Of Double)
    Friend R As Vector256(Of Double)
    Friend ColTime As Vector256(Of Double)

    ''' <summary>Writes one body's motion into lane k (0 … 3).</summary>
    Friend Sub SetLane(k As Integer, ByRef state As Motion, colTime As Double)
        Put(T0, k, state.T0)
        Put(Px, k, state.Px)
        Put(Py, k, state.Py)
        Put(Vx, k, state.Vx)
        Put(Vy, k, state.Vy)
        Put(Ay, k, PublishedAy(state))
        Put(R, k, state.R)
        Put(Me.ColTime, k, colTime)
    End Sub

    ''' <summary>
    ''' The vertical acceleration a lane shows: NaN when there is a horizontal one too, or when the body
    ''' is not a circle (R = 0: a polygon), whose pairs the quadratic of two circles does not describe.
    ''' </summary>
    Friend Shared Function PublishedAy(ByRef state As Motion) As Double
        Return If(state.Ax = 0 AndAlso state.R > 0, state.Ay, Double.NaN)
    End Function

    ''' <summary>Writes one body's next collision time (s) into lane k (0 … 3).</summary>
    Friend Sub SetColTime(k As Integer, value As Double)
        Put(ColTime, k, value)
    End Sub

    ''' <summary>Copies lane <paramref name="source"/> into lane <paramref name="target"/> (0 … 3).</summary>
    Friend Sub CopyLane(source As Integer, target As Integer)
        Put(T0, target, T0.GetElement(source))
        Put(Px, target, Px.GetElement(source))
        Put(Py, target, Py.GetElement(source))
        Put(Vx, target, Vx.GetElement(source))
        Put(Vy, target, Vy.GetElement(source))
        Put(Ay, target, Ay.GetElement(source))
        Put(R, target, R.GetElement(source))
        Put(ColTime, target, ColTime.GetElement(source))
    End Sub

    ''' <summary>
    ''' Stores one element in place. Vector256.WithElement would build a whole new vector for every
    ''' field, through the stack, which measurably slowed the whole solver.
    ''' </summary>
    Private Shared Sub Put(ByRef v As Vector256(Of Double), k As Integer, value As Double)
        Unsafe.Add(Unsafe.As(Of Vector256(Of Double), Double)(v), k) = value
    End Sub

    ''' <summary>Whether lane k holds exactly this body's motion (bit for bit).</summary>
    Friend Function LaneIs(k As Integer, ByRef state As Motion, colTime As Double) As Boolean
        Dim ay = PublishedAy(state)
        Return T0.GetElement(k).Equals(state.T0) AndAlso Px.GetElement(k).Equals(state.Px) AndAlso
               Py.GetElement(k).Equals(state.Py) AndAlso Vx.GetElement(k).Equals(state.Vx) AndAlso
               Vy.GetElement(k).Equals(state.Vy) AndAlso Me.Ay.GetElement(k).Equals(ay) AndAlso
               R.GetElement(k).Equals(state.R) AndAlso Me.ColTime.GetElement(k).Equals(colTime)
    End Function
End Structure
#End If
