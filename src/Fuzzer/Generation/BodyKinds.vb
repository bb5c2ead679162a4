Option Strict On

Namespace Generation
    ''' <summary>
    ''' The kinds of body a generated scene may hold. <see cref="BodyKinds.Default"/> is what the engine reads now;
    ''' the others are written to the format's specification and switched on when the engine reads them.
    ''' </summary>
    <Flags>
    Friend Enum BodyKinds
        None = 0
        ''' <summary>Circles, movable and fixed.</summary>
        Circle = 1
        ''' <summary>Fixed rectangles.</summary>
        Rectangle = 2
        ''' <summary>Fixed segments: ramps, shelves, V funnels.</summary>
        Segment = 4
        ''' <summary>Convex polygons, fixed and movable.</summary>
        Polygon = 8
        ''' <summary>Movable rectangles ("fixed": false).</summary>
        Box = 16
        ''' <summary>Springs, rods and strings ("links").</summary>
        Link = 32
        ''' <summary>The default: what the engine reads now, circles and fixed rectangles.</summary>
        [Default] = Circle Or Rectangle
        ''' <summary>Every kind the format describes.</summary>
        All = Circle Or Rectangle Or Segment Or Polygon Or Box Or Link
    End Enum
End Namespace
