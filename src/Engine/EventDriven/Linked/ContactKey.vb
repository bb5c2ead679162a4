Option Strict On

''' <summary>
''' Which contact a lasting contact is, in the linked event solver's numbering: a body with a
''' wall side, a fixed body, or another movable body (always the higher-numbered, so that a pair has one key).
''' Equal keys name the same contact whatever feature of the pair shape it is on.
''' </summary>
Friend NotInheritable Class ContactKey
    Implements IEquatable(Of ContactKey)

    Private Sub New(value As Long)
        Me.Value = value
    End Sub

    ''' <summary>Body i (lower) with movable body j (higher).</summary>
    Friend Shared Function Pair(i As Integer, j As Integer) As ContactKey
        Return New ContactKey(Encode(0, Math.Min(i, j), Math.Max(i, j)))
    End Function

    ''' <summary>Body i with a wall side.</summary>
    Friend Shared Function Wall(i As Integer, side As WallSide) As ContactKey
        Return New ContactKey(Encode(1, i, CInt(side)))
    End Function

    ''' <summary>Body i with fixed body f.</summary>
    Friend Shared Function Fixed(i As Integer, f As Integer) As ContactKey
        Return New ContactKey(Encode(2, i, f))
    End Function

    ''' <summary>The value of <see cref="Pair"/>(i, j)'s key, without making one.</summary>
    Friend Shared Function PairValue(i As Integer, j As Integer) As Long
        Return Encode(0, Math.Min(i, j), Math.Max(i, j))
    End Function

    ''' <summary>The value of <see cref="Wall"/>(i, side)'s key.</summary>
    Friend Shared Function WallValue(i As Integer, side As WallSide) As Long
        Return Encode(1, i, CInt(side))
    End Function

    ''' <summary>The value of <see cref="Fixed"/>(i, f)'s key.</summary>
    Friend Shared Function FixedValue(i As Integer, f As Integer) As Long
        Return Encode(2, i, f)
    End Function

    Private Shared Function Encode(kind As Integer, i As Integer, j As Integer) As Long
        Return (CLng(kind) << 60) Or (CLng(i) << 30) Or CLng(j)
    End Function

    ''' <summary>0 a pair of movable bodies, 1 a wall, 2 a fixed body.</summary>
    Friend ReadOnly Property Kind As Integer
        Get
            Return CInt(Value >> 60)
        End Get
    End Property

    ''' <summary>The (lower) body's index.</summary>
    Friend ReadOnly Property Body As Integer
        Get
            Return CInt((Value >> 30) And &H3FFFFFFFL)
        End Get
    End Property

    ''' <summary>The other: a movable body's index, a wall side, or a fixed body's index.</summary>
    Friend ReadOnly Property Other As Integer
        Get
            Return CInt(Value And &H3FFFFFFFL)
        End Get
    End Property

    ''' <summary>The key as one number.</summary>
    Friend ReadOnly Property Value As Long

    Public Overloads Function Equals(other As ContactKey) As Boolean Implements IEquatable(Of ContactKey).Equals
        Return other IsNot Nothing AndAlso other.Value = Value
    End Function

    Public Overrides Function Equals(obj As Object) As Boolean
        Return Equals(TryCast(obj, ContactKey))
    End Function

    Public Overrides Function GetHashCode() As Integer
        Return Value.GetHashCode()
    End Function
End Class
