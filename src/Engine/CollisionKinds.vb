Option Strict On

''' <summary>Which <see cref="CollisionKind"/> a collision is, from the shapes that met: one rule for every solver.</summary>
Friend Module CollisionKinds
    ''' <summary>
    ''' The kind of a collision of movable body <paramref name="a"/> with <paramref name="b"/> (Nothing for a
    ''' wall). Pairs the enumeration has no name for (a box, a polygon, a ramp) are <see cref="CollisionKind.Other"/>;
    ''' the kind name in the outputs then comes from the shapes themselves.
    ''' </summary>
    Friend Function Between(a As Shape, b As Shape) As CollisionKind
        If b Is Nothing Then Return AgainstWall(a.Kind)
        Return Between(a.Kind, b.Kind, b.IsFixed)
    End Function

    ''' <summary>
    ''' As <see cref="Between(Shape, Shape)"/>, from the kinds alone: the event solver keeps its bodies'
    ''' kinds in a table of its own, so that a collision need not reach into the shape objects (in a gas
    ''' of thousands of bodies, a cache miss each).
    ''' </summary>
    Friend Function Between(a As ShapeKind, b As ShapeKind, bIsFixed As Boolean) As CollisionKind
        If a <> ShapeKind.Circle Then Return CollisionKind.Other
        Select Case b
            Case ShapeKind.Circle : Return If(bIsFixed, CollisionKind.CircleFixed, CollisionKind.CircleCircle)
            Case ShapeKind.Rectangle : Return CollisionKind.CircleRectangle
            Case Else : Return CollisionKind.Other
        End Select
    End Function

    ''' <summary>The kind of a collision of a movable body of kind <paramref name="a"/> with a wall of the container.</summary>
    Friend Function AgainstWall(a As ShapeKind) As CollisionKind
        Return If(a = ShapeKind.Circle, CollisionKind.CircleWall, CollisionKind.Other)
    End Function
End Module
