Option Strict On

Namespace Scenes
    ''' <summary>One liquid region as read and checked from a scene file's "bodies" (type "liquid").</summary>
    Friend NotInheritable Class LiquidSpec
        ''' <summary>0-based position in the file's "bodies" array.</summary>
        Friend Property Index As Integer
        Friend Property Id As String
        ''' <summary>Lower-left corner and size, m.</summary>
        Friend Property X As Double
        Friend Property Y As Double
        Friend Property Width As Double
        Friend Property Height As Double
        ''' <summary>ρ_l, kg/m².</summary>
        Friend Property Density As Double
        Friend Property DragCoefficient As Double
        ''' <summary>b_l, N·s/m.</summary>
        Friend Property LinearDrag As Double
        Friend Property Color As String

        ''' <summary>Where error messages point: "bodies[3]".</summary>
        Friend ReadOnly Property Place As String
            Get
                Return SceneReader.BodyPlace(Index)
            End Get
        End Property

        ''' <summary>Builds the model liquid this spec describes.</summary>
        Friend Function ToLiquid() As Liquid
            Return New Liquid(New Vector(X, Y), Width, Height, Density, Id) With {
                .DragCoefficient = DragCoefficient, .LinearDrag = LinearDrag, .Color = Color}
        End Function
    End Class
End Namespace
