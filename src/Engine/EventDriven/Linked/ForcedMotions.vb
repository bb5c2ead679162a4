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
    ''' linked group (springs: <see cref="IntegratedMotion"/>; rods and strings: <see cref="ConstrainedMotion"/>), is
    ''' integrated with the forces as a term of its equations of motion. <paramref name="released"/>: a string of the
    ''' group that has just gone slack, whatever the rounding says.
    ''' </summary>
    Friend Function Create(group As LinkedGroup, world As World, time As Double, released As Object) As LinkedMotion
        Dim forces = FieldFor(group, world)
        If forces Is Nothing Then Return Nothing
        Dim g = world.Gravity
        If group.Links.Count > 0 Then
            If group.Links.All(Function(l) l.Kind = LinkKind.Spring) Then Return New IntegratedMotion(group.Bodies.ToArray(), group.Links, time, g, forces)
            Return New ConstrainedMotion(group.Bodies.ToArray(), group.Links, Array.Empty(Of Constraint)(), time, g, released, Size(group), Nothing, forces)
        End If
        Dim body = group.Bodies(0)
        ' Linear drag alone, and no liquid it could fly into: the exponential approach in closed form.
        If Not forces.HasLiquids AndAlso Not (world.AirDensity > 0 AndAlso body.DragCoefficient > 0) Then Return New LinearDragMotion(body, time, g)
        Return New DragMotion(body, time, g, forces)
    End Function

    ''' <summary>The forces of <paramref name="world"/> when they act on a body of <paramref name="group"/>; else Nothing.</summary>
    Friend Function FieldFor(group As LinkedGroup, world As World) As ForceField
        If Not world.HasDragOrLiquids Then Return Nothing
        Dim forces As New ForceField(world)
        Return If(group.Bodies.Any(Function(b) forces.Acts(b)), forces, Nothing)
    End Function

    ''' <summary>A length of the size of the group's smallest body, m (for an integrator's first step).</summary>
    Friend Function Size(group As LinkedGroup) As Double
        Return group.Bodies.Min(Function(body) Math.Min(body.Outline.MaxX - body.Outline.MinX, body.Outline.MaxY - body.Outline.MinY))
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
