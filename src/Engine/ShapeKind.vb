Option Strict On

''' <summary>The kinds of body a world can hold.</summary>
Public Enum ShapeKind
    ''' <summary>A circle, movable or fixed.</summary>
    Circle
    ''' <summary>An axis-aligned rectangle: a fixed obstacle, or a movable box that never rotates.</summary>
    Rectangle
    ''' <summary>A fixed straight line of no thickness, solid on both sides (a ramp, a shelf).</summary>
    Segment
    ''' <summary>A convex polygon, fixed or movable (it never rotates).</summary>
    Polygon
End Enum
