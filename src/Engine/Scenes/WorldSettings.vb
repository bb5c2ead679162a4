Option Strict On

Namespace Scenes
    ''' <summary>The "world" object of a scene file, checked.</summary>
    Friend NotInheritable Class WorldSettings
        ''' <summary>m</summary>
        Friend Property Width As Double
        ''' <summary>m</summary>
        Friend Property Height As Double
        ''' <summary>m/s², ≥ 0, towards −y</summary>
        Friend Property Gravity As Double
        Friend Property Restitution As Double
        Friend Property Walls As Boolean
        ''' <summary>μk, ≥ 0.</summary>
        Friend Property Friction As Double
        ''' <summary>μs, ≥ μk, or Nothing for the same as μk.</summary>
        Friend Property StaticFriction As Double?
        ''' <summary>ρ of the air, kg/m², ≥ 0.</summary>
        Friend Property AirDensity As Double
    End Class
End Namespace
