Option Strict On

''' <summary>
''' Which motion the linked event solver gives a body that drag or buoyancy act on (docs/forces.md, "In the event
''' solver"): linear drag alone in closed form (<see cref="LinearDragMotion"/>), anything else integrated with error
''' control (<see cref="DragMotion"/>); and what it cannot move yet, said in a plain sentence.
''' </summary>
Friend Module ForcedMotions
    ''' <summary>Throws <see cref="UnsupportedSceneException"/> when drag or buoyancy acts on a body that links hold.</summary>
    Friend Sub CheckSupported(world As World, groups As List(Of LinkedGroup))
        If Not world.HasDragOrLiquids Then Return
        Dim forces As New ForceField(world)
        For Each g In groups
            If g.Links.Count = 0 Then Continue For
            For Each b In g.Bodies
                If forces.Acts(b) Then Throw New UnsupportedSceneException("the event solver does not yet move a body on a link that feels drag or buoyancy ('" & b.Id & "'); use --solver verlet")
            Next
        Next
    End Sub

    ''' <summary>The motion of a free body that drag or buoyancy acts on, from its state now; Nothing when none does (or it has links).</summary>
    Friend Function Create(group As LinkedGroup, world As World, time As Double) As LinkedMotion
        If group.Links.Count > 0 OrElse group.Bodies.Count <> 1 OrElse Not world.HasDragOrLiquids Then Return Nothing
        Dim body = group.Bodies(0)
        Dim forces As New ForceField(world)
        If Not forces.Acts(body) Then Return Nothing
        ' Linear drag alone, and no liquid it could fly into: the exponential approach in closed form.
        If Not forces.HasLiquids AndAlso Not (world.AirDensity > 0 AndAlso body.DragCoefficient > 0) Then Return New LinearDragMotion(body, time, world.Gravity)
        Return New DragMotion(body, time, world.Gravity, forces)
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
