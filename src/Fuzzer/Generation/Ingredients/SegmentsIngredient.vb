Option Strict On

Namespace Generation
    ''' <summary>
    ''' One to three fixed segments: ramps, level shelves and V funnels (two segments meeting at their lowest
    ''' point), ends free to leave the container; with circles on, half the time a ball placed exactly on a
    ''' segment (its centre r from it along the upward normal).
    ''' </summary>
    Friend NotInheritable Class SegmentsIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "segments"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Segment

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim size = Math.Min(scene.World.Width, scene.World.Height)
            Dim count = rng.Between(1, 3)
            Dim made As New List(Of BodyDraft)
            For i = 1 To count
                For attempt = 1 To Attempts
                    Dim length = size * rng.Uniform(0.1, 0.6)
                    Dim p = New Vector(rng.Uniform(0, scene.World.Width), rng.Uniform(0, scene.World.Height))
                    Dim group As New List(Of BodyDraft)
                    Dim kind = rng.NextDouble()
                    If kind < 0.45 Then
                        Dim d = New Vector(1, rng.Uniform(-1, 1))
                        group.Add(BodyDraft.Segment(scene.NewId("s"), p, p + d / d.Length * length))
                    ElseIf kind < 0.7 Then
                        group.Add(BodyDraft.Segment(scene.NewId("s"), p, p + New Vector(length, 0)))
                    Else
                        Dim left = New Vector(-rng.Uniform(0.2, 1), 1)
                        Dim right = New Vector(rng.Uniform(0.2, 1), 1)
                        group.Add(BodyDraft.Segment(scene.NewId("s"), p + left / left.Length * length, p))
                        group.Add(BodyDraft.Segment(scene.NewId("s"), p, p + right / right.Length * length))
                    End If
                    If scene.TryAddAll(group) Then
                        made.AddRange(group)
                        Exit For
                    End If
                Next
            Next
            If made.Count = 0 OrElse Not scene.Has(BodyKinds.Circle) OrElse Not rng.Chance(0.5) Then Return
            For attempt = 1 To Attempts
                Dim s = rng.Pick(made)
                Dim along = s.EndPoint - s.Position
                Dim n = New Vector(-along.Y, along.X) / along.Length
                If n.Y < 0 Then n = -n
                If n.Y = 0 Then Continue For
                Dim r = scene.Radius()
                Dim foot = s.Position + along * rng.Uniform(0.1, 0.9)
                If scene.TryAdd(scene.Ball(foot + n * r, r, Vector.Zero)) Then Exit For
            Next
        End Sub
    End Class
End Namespace
