Option Strict On

''' <summary>
''' Which motion the linked event solver gives a body that drag or buoyancy act on (docs/forces.md, "In the event
''' solver"): linear drag alone in closed form (<see cref="LinearDragMotion"/>), anything else integrated with error
''' control (<see cref="DragMotion"/>, or for linked bodies the springs' and chains' integrators with the forces added).
''' </summary>
Friend Module ForcedMotions
    ''' <summary>
    ''' What the event solver says of a scene with friction: friction at a resting contact belongs to the same solve as
    ''' the resting contact itself, which the event solver does not do yet; moving such a scene as if every surface
    ''' were ice would teach the wrong physics without a word, so it is refused before anything moves.
    ''' </summary>
    Friend Const NoFriction As String = "the event solver does not yet apply friction (this scene has rough surfaces); use --solver verlet"

    ''' <summary>
    ''' The motion of a group that drag or buoyancy acts on, from its state now; Nothing when none does. A free body
    ''' with linear drag alone, in a world without liquids, moves in closed form; any other free body, and every
    ''' linked group (springs: <see cref="IntegratedMotion"/>; rods and strings: <see cref="ChainMotion"/>), is
    ''' integrated with the forces as a term of its equations of motion. <paramref name="slack"/>: a string of the
    ''' group has just gone slack, whatever the rounding says.
    ''' </summary>
    Friend Function Create(group As LinkedGroup, world As World, time As Double, slack As Boolean) As LinkedMotion
        If Not world.HasDragOrLiquids Then Return Nothing
        Dim forces As New ForceField(world)
        If Not group.Bodies.Any(Function(b) forces.Acts(b)) Then Return Nothing
        Dim g = world.Gravity
        If group.Links.Count > 0 Then
            If group.Links.All(Function(l) l.Kind = LinkKind.Spring) Then Return New IntegratedMotion(group.Bodies.ToArray(), group.Links, time, g, forces)
            Dim previous = TryCast(group.Motion, ChainMotion)
            Return New ChainMotion(group.Bodies.ToArray(), group.Links, time, g, If(slack AndAlso previous IsNot Nothing, previous.Slackened, Nothing), forces)
        End If
        Dim body = group.Bodies(0)
        ' Linear drag alone, and no liquid it could fly into: the exponential approach in closed form.
        If Not forces.HasLiquids AndAlso Not (world.AirDensity > 0 AndAlso body.DragCoefficient > 0) Then Return New LinearDragMotion(body, time, g)
        Return New DragMotion(body, time, g, forces)
    End Function

    ''' <summary>
    ''' Whether the rest rules (which know gravity alone) must leave this body be, touching faces of the given unit normals
    ''' (docs/forces.md, section 6). A body drag and buoyancy do not act on: no. One the liquids push up at least as hard
    ''' as it weighs: yes (it floats off). One still (slower than <paramref name="restingSpeed"/>): no, it may rest,
    ''' since drag is then zero and the face holds it exactly. One moving on level faces only, with no drag that could
    ''' slow it: no, it slides on at its speed, as the rest rules move it. Otherwise (drag would slow its slide, or a
    ''' liquid would lighten it on a slope, neither of which the rest rules know) it is not rested; and if it is
    ''' settling onto a face all the same (its speed across the face within a bounce of four slops), it would bounce
    ''' for ever a slop deeper each time: refused, in words, with <see cref="UnsupportedSceneException"/>.
    ''' </summary>
    Friend Function KeepsFromResting(body As Shape, world As World, restingSpeed As Double, normals As IReadOnlyList(Of Vector)) As Boolean
        If Not world.HasDragOrLiquids Then Return False
        Dim forces As New ForceField(world)
        If Not forces.Acts(body) Then Return False
        Dim resistance As Double, lift As Double
        forces.Evaluate(body, body.Position, body.Velocity, resistance, lift)
        If lift >= body.Mass * world.Gravity Then Return True
        Dim v = body.Velocity
        If v.Length <= restingSpeed Then Return False
        If Not forces.CanDrag(body) AndAlso normals.All(Function(n) n.Y >= RestingFaces.LevelCosine) Then Return False
        For Each n In normals
            If n.Y > 0 AndAlso Math.Abs(Vector.Dot(v, n)) <= restingSpeed Then
                Throw New UnsupportedSceneException("the event solver does not yet let a body that feels drag or buoyancy ('" & body.Id &
                    "') come to rest while it slides along what it touches; use --solver verlet")
            End If
        Next
        Return True
    End Function
    ''' <summary>What drag and buoyancy add to a body's acceleration in its state now (written to it), m/s²; zero when none act.</summary>
    Friend Function Acceleration(body As Shape, world As World) As Vector
        If Not world.HasDragOrLiquids Then Return Vector.Zero
        Dim forces As New ForceField(world)
        If Not forces.Acts(body) Then Return Vector.Zero
        Dim power As Double
        Return forces.Force(body, body.Position, body.Velocity, power) * body.InverseMass
    End Function
End Module
