Option Strict On

''' <summary>How the event-driven solver currently moves a movable circle.</summary>
Friend Enum BodyMode As Byte
    ''' <summary>Free flight on a parabola under gravity.</summary>
    Free
    ''' <summary>On an upward-facing surface (floor, rectangle top), moving only horizontally; no gravity.</summary>
    Resting
    ''' <summary>Asleep in a pile: a fixed obstacle until something hits it hard enough to wake it.</summary>
    Sleeping
    ''' <summary>Dragged: straight-line motion to the drag target, infinite mass, no gravity.</summary>
    Dragged
    ''' <summary>Sliding over a rectangle's corner until the normal force vanishes.</summary>
    Sliding
End Enum
