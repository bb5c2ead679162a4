Option Strict On

''' <summary>How the event-driven solver currently moves a movable body.</summary>
Friend Enum BodyMode As Byte
    ''' <summary>Free flight on a parabola under gravity.</summary>
    Free
    ''' <summary>Held on a level support (floor, a rectangle's top, a body at rest), moving only along it; no gravity.</summary>
    Supported
    ''' <summary>Asleep in a pile: a fixed obstacle until something hits it hard enough to wake it.</summary>
    Sleeping
    ''' <summary>Dragged: straight-line motion to the drag target, infinite mass, no gravity.</summary>
    Dragged
    ''' <summary>Sliding round a corner on a circular arc until the normal force vanishes.</summary>
    Rounding
End Enum
