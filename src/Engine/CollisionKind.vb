Option Strict On

''' <summary>What a movable circle hit.</summary>
Public Enum CollisionKind
    ''' <summary>Another movable circle.</summary>
    CircleCircle
    ''' <summary>A fixed circle.</summary>
    CircleFixed
    ''' <summary>A rectangle (a face or a corner).</summary>
    CircleRectangle
    ''' <summary>A side of the container.</summary>
    CircleWall
End Enum
