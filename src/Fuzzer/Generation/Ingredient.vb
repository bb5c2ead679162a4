Option Strict On

Namespace Generation
    ''' <summary>
    ''' One way of adding bodies to a scene (scattered balls, a cradle row, a ball on a corner, …). Each
    ''' names the kinds of body it needs, so a kind the engine does not read yet is never generated unless
    ''' it is switched on.
    ''' </summary>
    Friend MustInherit Class Ingredient
        ''' <summary>A short name, as coverage counts and failure reports give it.</summary>
        Friend MustOverride ReadOnly Property Name As String

        ''' <summary>Every kind it may write; it is used only when all are switched on.</summary>
        Friend MustOverride ReadOnly Property Needs As BodyKinds

        ''' <summary>Adds what it can within the scene's budget; may add nothing when nothing fits.</summary>
        Friend MustOverride Sub Apply(scene As SceneBuilder)

        ''' <summary>How many times an ingredient tries a random placement before it gives up.</summary>
        Protected Const Attempts As Integer = 30
    End Class
End Namespace
