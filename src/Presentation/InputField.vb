Option Strict On

''' <summary>The text boxes of the side panel.</summary>
Public Enum InputField
    ''' <summary>Circle radius, m.</summary>
    Radius = 0
    ''' <summary>Circle mass, kg.</summary>
    Mass
    ''' <summary>Rectangle width, m.</summary>
    RectangleWidth
    ''' <summary>Rectangle height, m.</summary>
    RectangleHeight
    ''' <summary>Container width, m.</summary>
    ContainerWidth
    ''' <summary>Container height, m.</summary>
    ContainerHeight
    ''' <summary>A regular polygon's number of sides.</summary>
    Sides
    ''' <summary>A regular polygon's turn, degrees anticlockwise.</summary>
    PolygonAngle
    ''' <summary>A spring's stiffness k, N/m.</summary>
    Stiffness
    ''' <summary>The world's coefficient of kinetic (sliding) friction μk.</summary>
    FrictionKinetic
    ''' <summary>The world's coefficient of static friction μs (empty: the same as μk).</summary>
    FrictionStatic
    ''' <summary>The density of the next liquid drawn, kg/m².</summary>
    LiquidDensity
End Enum
