Option Strict On

''' <summary>
''' What the event-driven solver keeps of one movable body besides its motion: its inverse mass, reach,
''' size and kind. Kept together (32 bytes) because a collision reads most of them for both bodies:
''' one cache line instead of one per array, which in a gas of thousands of bodies is most of the cost
''' of reading them.
''' </summary>
Friend Structure BodyInfo
    ''' <summary>1/kg; 0 while the body is dragged (it pushes and is not pushed back).</summary>
    Friend InverseMass As Double
    ''' <summary>How far the body reaches from its reference point, m (a circle's radius).</summary>
    Friend Reach As Double
    ''' <summary>The body's size for the resting rules' thresholds, m: a circle's radius, else the radius of a disc of the same area.</summary>
    Friend Scale As Double
    ''' <summary>The body's kind (so that no hot path need reach into the shape object).</summary>
    Friend Kind As ShapeKind
    ''' <summary>True for a circle: the pair tests of two circles have a fast path of their own.</summary>
    Friend IsCircle As Boolean
End Structure
