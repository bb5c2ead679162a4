Option Strict On

''' <summary>
''' A support that curves and does not move (a fixed circle, a rounded corner of a fixed body, a ball
''' asleep): the centre and radius of the arc a body's reference point moves on while it slides round
''' it, and the normals where the arc ends on a face (none for a full circle).
''' </summary>
Friend Structure CurvedSupport
    ''' <summary>Centre of the arc, m.</summary>
    Friend Centre As Vector
    ''' <summary>Radius of the arc, m (the pair's rounding radius).</summary>
    Friend Radius As Double
    ''' <summary>The normals of the two faces the corner joins, or Nothing for a full circle.</summary>
    Friend Cone As (Vector, Vector)?
End Structure
