Option Strict On

''' <summary>What a movable circle hit; <see cref="Other"/> for every pair with another kind of body.</summary>
Public Enum CollisionKind
    ''' <summary>Another movable circle.</summary>
    CircleCircle
    ''' <summary>A fixed circle.</summary>
    CircleFixed
    ''' <summary>A rectangle (a face or a corner).</summary>
    CircleRectangle
    ''' <summary>A side of the container.</summary>
    CircleWall
    ''' <summary>Any other pair (a box, a polygon or a segment is involved): see <see cref="CollisionRecord.KindName"/>.</summary>
    Other
    ''' <summary>A string snapping taut: the jerk along it (<see cref="CollisionRecord.Link"/> names it).</summary>
    StringTaut
End Enum
