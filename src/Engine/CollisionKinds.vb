Option Strict On

''' <summary>Which <see cref="CollisionKind"/> a collision is, from the shapes that met: one rule for every solver.</summary>
Friend Module CollisionKinds
    ''' <summary>
    ''' The kind of a collision of movable body <paramref name="a"/> with <paramref name="b"/> (Nothing for a
    ''' wall). Pairs the enumeration has no name for (a box, a polygon, a ramp) are <see cref="CollisionKind.Other"/>;
    ''' the kind name in the outputs then comes from the shapes themselves.
    ''' </summary>
    Friend Function Between(a As Shape, b As Shape) As CollisionKind
        If a.Kind <> ShapeKind.Circle Then Return CollisionKind.Other
        If b Is Nothing Then Return CollisionKind.CircleWall
        Select Case b.Kind
            Case ShapeKind.Circle : Return If(b.IsFixed, CollisionKind.CircleFixed, CollisionKind.CircleCircle)
            Case ShapeKind.Rectangle : Return CollisionKind.CircleRectangle
            Case Else : Return CollisionKind.Other
        End Select
    End Function
End Module
