Option Strict On

Namespace Generation
    ''' <summary>
    ''' One to four links between the scene's bodies: springs (stiffness over five decades, with or without
    ''' a rest length and damping), rods and strings, to another body or to a fixed point; a third of them
    ''' are pendulums, a ball on a rod or string from a point straight above it.
    ''' </summary>
    Friend NotInheritable Class LinksIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "links"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Link

        Private Shared ReadOnly Types As String() = {"spring", "rod", "string"}

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim movable = scene.Bodies.Where(Function(b) Not b.IsFixed).ToList()
            If movable.Count = 0 Then Return
            Dim count = rng.Between(1, 4)
            For i = 1 To count
                Dim a = rng.Pick(movable)
                Dim link As New LinkDraft With {.Id = scene.NewId("l"), .A = a.Id}
                Dim pa = a.ReferencePoint
                Dim pb As Vector
                If rng.Chance(0.33) Then
                    link.Type = If(rng.Chance(0.5), "string", "rod")
                    pb = pa + New Vector(0, Math.Min(scene.World.Height, 1.0) * rng.Uniform(0.1, 1))
                    link.At = pb
                Else
                    link.Type = rng.Pick(Types)
                    Dim others = scene.Bodies.Where(Function(b) b IsNot a AndAlso Not (b.Shape = DraftShape.Segment)).ToList()
                    If others.Count > 0 AndAlso rng.Chance(0.6) Then
                        Dim b = rng.Pick(others)
                        link.B = b.Id
                        pb = b.ReferencePoint
                    Else
                        pb = pa + rng.Direction() * scene.RadiusMax * rng.Uniform(2, 10)
                        link.At = pb
                    End If
                End If
                Dim distance = Vector.Hypot(pb.X - pa.X, pb.Y - pa.Y)
                If distance = 0 AndAlso link.Type <> "spring" Then Continue For
                Select Case link.Type
                    Case "spring"
                        link.Stiffness = rng.LogUniform(1, 100000.0)
                        If rng.Chance(0.5) Then link.RestLength = distance * rng.Uniform(0, 2)
                        If rng.Chance(0.3) Then link.Damping = rng.LogUniform(0.001, 10)
                    Case "rod"
                        If rng.Chance(0.3) Then link.Length = distance
                    Case Else
                        If rng.Chance(0.5) Then link.Length = distance * rng.Uniform(1, 1.5)
                End Select
                scene.Links.Add(link)
            Next
        End Sub
    End Class
End Namespace
