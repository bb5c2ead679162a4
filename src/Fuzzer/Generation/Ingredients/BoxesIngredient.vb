Option Strict On

Namespace Generation
    ''' <summary>
    ''' One to four movable boxes ("rectangle" with "fixed": false): some exactly on the floor or a fixed
    ''' rectangle's top, some stacked exactly on another box, the rest anywhere, moving as balls do.
    ''' </summary>
    Friend NotInheritable Class BoxesIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "boxes"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Box

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim count = rng.Between(1, 4)
            Dim made As New List(Of BodyDraft)
            For i = 1 To count
                For attempt = 1 To Attempts
                    Dim w = 2 * scene.Radius() * rng.Uniform(0.5, 2)
                    Dim h = 2 * scene.Radius() * rng.Uniform(0.5, 2)
                    Dim corner As Vector
                    Dim velocity = scene.Velocity()
                    Dim u = rng.NextDouble()
                    Dim supports = scene.Supports(w)
                    If u < 0.4 AndAlso supports.Count > 0 Then
                        Dim s = rng.Pick(supports)
                        corner = New Vector(rng.Uniform(s.Left, s.Right - w), s.Top)
                        velocity = scene.Sliding()
                    ElseIf u < 0.6 AndAlso made.Count > 0 Then
                        Dim below = rng.Pick(made)
                        corner = New Vector(below.Position.X + rng.Uniform(-w, below.Width) * 0.9, below.Corner.Y)
                        velocity = Vector.Zero
                    Else
                        corner = New Vector(rng.Uniform(0, scene.World.Width - w), rng.Uniform(0, scene.World.Height - h))
                    End If
                    Dim box = BodyDraft.Box(scene.NewId("b"), corner, w, h, scene.Mass(), velocity)
                    If scene.TryAdd(box) Then
                        made.Add(box)
                        Exit For
                    End If
                Next
            Next
        End Sub
    End Class
End Namespace
