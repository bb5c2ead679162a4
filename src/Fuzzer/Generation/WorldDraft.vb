Option Strict On

Namespace Generation
    ''' <summary>The "world" object of a generated scene.</summary>
    Friend NotInheritable Class WorldDraft
        ''' <summary>Container size, m.</summary>
        Friend Property Width As Double
        Friend Property Height As Double
        ''' <summary>g, m/s².</summary>
        Friend Property Gravity As Double
        ''' <summary>e in [0, 1].</summary>
        Friend Property Restitution As Double
        Friend Property Walls As Boolean
        ''' <summary>μk and μs of every surface (0: no friction, and the fields are left out).</summary>
        Friend Property Friction As Double
        Friend Property StaticFriction As Double

        ''' <summary>The world as one physics-scene/1 object, every field explicit.</summary>
        Friend Function ToJson() As String
            Dim json = New JsonText().Add("width", Width).Add("height", Height).Add("gravity", Gravity).Add("restitution", Restitution).Add("walls", Walls)
            If Friction > 0 Then json.Add("friction", Friction).Add("static_friction", StaticFriction)
            Return json.ToString()
        End Function
    End Class
End Namespace
