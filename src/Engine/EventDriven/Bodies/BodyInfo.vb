Option Strict On

''' <summary>
''' What every collision reads and writes of a movable body besides its motion and schedule: its
''' inverse mass and kind, and its last hits as the resting rules count them (<see cref="RestRules"/>
''' owns those three fields: it alone writes them). Kept together, 32 bytes, because a collision
''' touches all of them for both bodies: at most two cache lines per body, and in a gas of ten
''' thousand bodies a quarter of a megabyte in all, where one array per field, or a record holding
''' the rarely read sizes too, spread the same reads over twice the memory. The sizes are in
''' <see cref="BodySize"/>, the rest of the hit history in <see cref="BurstHistory"/>.
''' </summary>
Friend Structure BodyInfo
    ''' <summary>1/kg; 0 while the body is dragged (it pushes and is not pushed back).</summary>
    Friend InverseMass As Double
    ''' <summary>Time of the body's last collision, s (for the inelastic-collapse guard); −∞ before the first.</summary>
    Friend LastHit As Double
    ''' <summary>Instant of the body's last collision, s (jam detection); NaN before the first.</summary>
    Friend SameTime As Double
    ''' <summary>Collisions at <see cref="SameTime"/> after the first.</summary>
    Friend SameCount As Integer
    ''' <summary>The body's kind (so that no hot path need reach into the shape object).</summary>
    Friend Kind As ShapeKind

    ''' <summary>A body of this kind that has not collided yet.</summary>
    Friend Shared Function Fresh(kind As ShapeKind) As BodyInfo
        Dim info = New BodyInfo() With {.Kind = kind}
        info.ResetHits()
        Return info
    End Function

    ''' <summary>Forgets the body's hits: as if it had not collided yet.</summary>
    Friend Sub ResetHits()
        LastHit = Double.NegativeInfinity
        SameTime = Double.NaN
        SameCount = 0
    End Sub

    ''' <summary>True for a circle: the pair tests of two circles have a fast path of their own.</summary>
    Friend ReadOnly Property IsCircle As Boolean
        Get
            Return Kind = ShapeKind.Circle
        End Get
    End Property
End Structure
