Option Strict On

''' <summary>
''' The bounds on what the teacher can type, and the messages a teacher sees when a value is out of range. A value
''' beyond a bound is brought to it, and the message says so; empty, zero, negative or non-numeric
''' values bring a message asking for suitable values. The lower bounds keep every derived number
''' finite and readable: a 1 cm ball is still drawn, its density and the cue's Δv = J/m stay below
''' 10⁶, and kinetic energy never overflows.
''' </summary>
Public Module InputLimits
    ''' <summary>Smallest circle radius, m.</summary>
    Public Const MinRadius As Double = 0.01
    ''' <summary>Largest circle radius, m.</summary>
    Public Const MaxRadius As Double = 2.0
    ''' <summary>Smallest mass, kg.</summary>
    Public Const MinMass As Double = 0.01
    ''' <summary>Largest mass, kg.</summary>
    Public Const MaxMass As Double = 1000.0
    ''' <summary>Smallest rectangle side, m.</summary>
    Public Const MinSide As Double = 0.01
    ''' <summary>Largest rectangle side, m.</summary>
    Public Const MaxSide As Double = 20.0
    ''' <summary>Largest container side, m.</summary>
    Public Const MaxContainer As Double = 100.0
    ''' <summary>Smallest container side, m: below this the bodies of a class demo would not fit.</summary>
    Public Const MinContainer As Double = 0.5

    ''' <summary>Fewest sides of a regular polygon (a triangle).</summary>
    Public Const MinSides As Integer = 3
    ''' <summary>Most sides of a regular polygon: more would look like a circle on a projector.</summary>
    Public Const MaxSides As Integer = 12
    ''' <summary>Largest turn of a polygon that is typed, degrees either way.</summary>
    Public Const MaxAngle As Double = 360.0
    ''' <summary>Softest spring, N/m.</summary>
    Public Const MinStiffness As Double = 0.1
    ''' <summary>Stiffest spring, N/m: stiffer would oscillate faster than the screen can show.</summary>
    Public Const MaxStiffness As Double = 10000.0

    ''' <summary>Asked when a circle's radius or mass is missing, zero or not a number.</summary>
    Public Const CircleMessage As String = "Please enter a suitable value for the mass and radius!"
    ''' <summary>Asked when a rectangle's width or height is missing, zero or not a number.</summary>
    Public Const RectangleMessage As String = "Please enter a suitable value for the width and height!"
    ''' <summary>Asked when a polygon's sides, size, angle or mass is missing, zero or not a number.</summary>
    Public Const PolygonMessage As String = "Please enter a suitable value for the sides, radius, angle and mass!"
    ''' <summary>Asked when the mass of a polygon drawn by its corners is missing, zero or not a number.</summary>
    Public Const CornersMessage As String = "Please enter a suitable value for the mass!"
    ''' <summary>Asked when a box's mass is missing, zero or not a number.</summary>
    Public Const BoxMessage As String = "Please enter a suitable value for the width, height and mass!"
    ''' <summary>Asked when a spring's stiffness is missing, zero or not a number.</summary>
    Public Const SpringMessage As String = "Please enter a suitable value for the spring's stiffness k!"
    ''' <summary>Asked when the container's size is missing, zero or not a number.</summary>
    Public Const ContainerMessage As String = "Please enter a suitable value for the container's width and height!"
    ''' <summary>Shown when Add is pressed while the previous body still follows the cursor.</summary>
    Public Const SpawnFirstMessage As String = "Please spawn your current object first!"
End Module
