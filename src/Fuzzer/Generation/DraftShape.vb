Option Strict On

Namespace Generation
    ''' <summary>The body types of physics-scene/1.</summary>
    Friend Enum DraftShape
        ''' <summary>"circle": movable or fixed.</summary>
        Circle
        ''' <summary>"rectangle": a fixed obstacle, or with "fixed": false a movable box.</summary>
        Rectangle
        ''' <summary>"segment": a fixed line.</summary>
        Segment
        ''' <summary>"polygon": convex, fixed or movable.</summary>
        Polygon
    End Enum
End Namespace
