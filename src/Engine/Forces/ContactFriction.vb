Option Strict On

''' <summary>
''' Coulomb's law of friction at a contact, as impulses (docs/forces.md, "Friction"). Two surfaces in contact
''' with coefficient μ: a contact that is not sliding stays so while the friction it needs is at most μs times
''' the normal force; one that slides feels μk times the normal force against its sliding. Over a short time
''' (a step, a blow) force × time is impulse, so the same law holds for the normal impulse j_n and the
''' tangential impulse j_t. A contact's coefficients are the geometric means of its two surfaces', √(μa μb),
''' as Box2D does: a surface of μ = 0 (ice) makes every contact with it frictionless.
''' </summary>
Public Module ContactFriction
    ''' <summary>√(μa μb): the coefficient of a contact between surfaces of μa and μb.</summary>
    Public Function Mean(a As Double, b As Double) As Double
        Return Math.Sqrt(a * b)
    End Function

    ''' <summary>
    ''' Gives a lasting contact <paramref name="c"/> between <paramref name="a"/> and <paramref name="b"/> (Nothing for a
    ''' wall) its Coulomb coefficients, the mean of the two surfaces' (<see cref="Mean"/>): only on a flat face, and only
    ''' between bodies that do not turn (a ball would roll: docs/forces.md). Elsewhere, or in a world without
    ''' friction, the contact keeps none.
    ''' </summary>
    Friend Sub Give(world As World, c As Constraint, a As Shape, b As Shape)
        If c.Shape <> ConstraintShape.Plane OrElse Not world.HasFriction Then Return
        If a.Kind = ShapeKind.Circle OrElse (b IsNot Nothing AndAlso b.Kind = ShapeKind.Circle) Then Return
        c.Friction = Mean(world.KineticFrictionOf(a), world.KineticFrictionOf(b))
        c.StaticFriction = Mean(world.StaticFrictionOf(a), world.StaticFrictionOf(b))
    End Sub

    ''' <summary>
    ''' The size (N·s, ≥ 0) of the tangential impulse against a slip of <paramref name="slip"/> m/s (≥ 0) at a
    ''' contact whose normal impulse was <paramref name="normalImpulse"/> N·s. Stopping the slip takes
    ''' m_eff × slip (m_eff = 1/(1/m_A + 1/m_B), kg): if that is at most μs j_n the contact sticks (the slip is
    ''' stopped exactly); otherwise it slides, and friction gives μk j_n, but never more than stopping takes,
    ''' so friction never reverses the sliding.
    ''' </summary>
    Public Function TangentialImpulse(slip As Double, effectiveMass As Double, normalImpulse As Double,
                                      staticCoefficient As Double, kineticCoefficient As Double) As Double
        If Not (slip > 0) OrElse Not (normalImpulse > 0) Then Return 0
        Dim needed = effectiveMass * slip
        If needed <= staticCoefficient * normalImpulse Then Return needed
        Return Math.Min(kineticCoefficient * normalImpulse, needed)
    End Function

    ''' <summary>
    ''' Whether a block on a slope at angle θ (rad) stays at rest: the friction it needs, m g sin θ, is at most
    ''' μs m g cos θ, i.e. tan θ ≤ μs (the angle of repose is tan⁻¹ μs).
    ''' </summary>
    Public Function HoldsOnSlope(angle As Double, staticCoefficient As Double) As Boolean
        Return Math.Tan(angle) <= staticCoefficient
    End Function

    ''' <summary>The acceleration (m/s²) down a slope at angle θ of a block sliding down it: g (sin θ − μk cos θ).</summary>
    Public Function SlidingAcceleration(angle As Double, gravity As Double, kineticCoefficient As Double) As Double
        Return gravity * (Math.Sin(angle) - kineticCoefficient * Math.Cos(angle))
    End Function

    ''' <summary>The distance (m) a block sliding at v (m/s) on a level rough floor goes before it stops: v²/(2 μk g), at time v/(μk g).</summary>
    Public Function StoppingDistance(speed As Double, gravity As Double, kineticCoefficient As Double) As Double
        Return speed * speed / (2 * kineticCoefficient * gravity)
    End Function
End Module
