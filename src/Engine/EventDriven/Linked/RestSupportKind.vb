Option Strict On

''' <summary>What a resting body in the linked event solver rests on: the container's floor or a side wall, a fixed body, or a movable body that itself rests level.</summary>
Friend Enum RestSupportKind As Byte
    ''' <summary>A wall of the container (<see cref="RestSupport.Index"/> is its <see cref="WallSide"/>).</summary>
    Wall
    ''' <summary>A fixed body (<see cref="RestSupport.Index"/> indexes the solver's fixed bodies).</summary>
    Fixed
    ''' <summary>A movable body resting level (<see cref="RestSupport.Index"/> indexes the solver's movable bodies).</summary>
    Body
End Enum
