Option Strict On

''' <summary>
''' Which motion the linked event solver gives a body that drag or buoyancy act on (docs/forces.md, "In the event
''' solver"): linear drag alone in closed form (<see cref="LinearDragMotion"/>), anything else integrated with error
''' control (<see cref="DragMotion"/>, or for linked bodies the springs' and chains' integrators with the forces added).
''' </summary>
Friend Module ForcedMotions
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
    ''' Whether the rest rules (which know gravity alone) must leave this body be: drag or buoyancy acts on it and
    ''' it is moving (drag would slow its slide along a face, which a resting motion at constant speed does not),
    ''' or the liquids push it up at least as hard as it weighs (it would float off the face). A body that drag
    ''' acts on may rest when it is still and pressed down: drag is then zero and the face holds it, exactly.
    ''' </summary>
    Friend Function KeepsFromResting(body As Shape, world As World, restingSpeed As Double) As Boolean
        If Not world.HasDragOrLiquids Then Return False
        Dim forces As New ForceField(world)
        If Not forces.Acts(body) Then Return False
        If body.Velocity.Length > restingSpeed Then Return True
        Dim resistance As Double, lift As Double
        forces.Evaluate(body, body.Position, body.Velocity, resistance, lift)
        Return lift >= body.Mass * world.Gravity
    End Function
End Module
