Option Strict On

''' <summary>What a cell of a body table holds, when the teacher can type a new value into it.</summary>
Public Enum TableQuantity
    ''' <summary>Not editable (id, colour, kind, speed, density, area, a rectangle's size).</summary>
    None
    ''' <summary>x of the point the table lists (a circle's centre, a rectangle's lower-left corner, a body's centre of mass), m.</summary>
    X
    ''' <summary>y of that point, m.</summary>
    Y
    ''' <summary>Horizontal velocity, m/s.</summary>
    Vx
    ''' <summary>Vertical velocity, m/s.</summary>
    Vy
    ''' <summary>Mass, kg.</summary>
    Mass
    ''' <summary>A circle's radius, m.</summary>
    Radius
    ''' <summary>A box's or polygon's width × height (m), or a ball's radius where a table lists sizes.</summary>
    Size
    ''' <summary>μk of the body's own surface (empty: the world's); boxes, polygons, fixed bodies and ramps, not balls.</summary>
    KineticFriction
    ''' <summary>μs of the body's own surface (empty: its own μk when set, else the world's μs).</summary>
    StaticFriction
End Enum
