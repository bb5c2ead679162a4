Option Strict On

''' <summary>What a body's next collision-type event is (its next cell crossing is kept apart).</summary>
Friend Enum EventKind As Byte
    ''' <summary>Nothing scheduled (time +∞).</summary>
    None
    ''' <summary>It touches another movable body.</summary>
    Body
    ''' <summary>It touches a fixed obstacle (the feature says which face or corner).</summary>
    Obstacle
    ''' <summary>It touches a side of the container.</summary>
    Wall
    ''' <summary>A supported body reaches the end of what holds it.</summary>
    LeaveSupport
    ''' <summary>A body sliding round a corner leaves it.</summary>
    CornerEnd
End Enum
