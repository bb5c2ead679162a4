Option Strict On

''' <summary>
''' The bounds on what the teacher can type, and the messages the seed's tests ask for. A value over
''' a bound is clamped to it; empty, zero or negative values bring a message asking for valid values.
''' </summary>
Public Module InputLimits
    ''' <summary>Largest circle radius, m.</summary>
    Public Const MaxRadius As Double = 2.0
    ''' <summary>Largest mass, kg.</summary>
    Public Const MaxMass As Double = 1000.0
    ''' <summary>Largest rectangle side, m.</summary>
    Public Const MaxSide As Double = 20.0
    ''' <summary>Largest container side, m.</summary>
    Public Const MaxContainer As Double = 100.0
    ''' <summary>Smallest container side, m: below this the bodies of a class demo would not fit.</summary>
    Public Const MinContainer As Double = 0.5

    ''' <summary>Asked when a circle's radius or mass is missing, zero or not a number.</summary>
    Public Const CircleMessage As String = "Please enter a suitable value for the mass and radius!"
    ''' <summary>Asked when a rectangle's width or height is missing, zero or not a number.</summary>
    Public Const RectangleMessage As String = "Please enter a suitable value for the width and height!"
    ''' <summary>Asked when the container's size is missing, zero or not a number.</summary>
    Public Const ContainerMessage As String = "Please enter a suitable value for the container's width and height!"
    ''' <summary>Shown when Add is pressed while the previous body still follows the cursor.</summary>
    Public Const SpawnFirstMessage As String = "Please spawn your current object first!"
End Module
