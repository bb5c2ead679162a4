Option Strict On

''' <summary>What a scheduled event is.</summary>
Friend Enum EventKind As Byte
    ''' <summary>Nothing scheduled (time +∞).</summary>
    None
    ''' <summary>Two movable circles touch.</summary>
    Circle
    ''' <summary>A movable circle touches a fixed circle.</summary>
    FixedCircle
    ''' <summary>A movable circle touches a rectangle (face or corner in the feature).</summary>
    Rectangle
    ''' <summary>A movable circle touches a side of the container.</summary>
    Wall
    ''' <summary>A resting circle's centre reaches the edge of the rectangle it rests on.</summary>
    EdgeLeave
    ''' <summary>A circle sliding over a corner leaves it.</summary>
    SlideEnd
End Enum
