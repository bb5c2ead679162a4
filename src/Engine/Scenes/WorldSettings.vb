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
    End Class
End Namespace
