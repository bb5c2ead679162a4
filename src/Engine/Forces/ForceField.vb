Option Strict On

''' <summary>
''' Every force on a movable body besides gravity, contacts and links (docs/forces.md): linear drag −b v in air
''' and liquid alike, quadratic air drag −½ ρ C_d L |v| v, and in each liquid buoyancy ρ_l g A_sub upwards and
''' the liquid's drag times the fraction of the body inside it. Read from the world once (its air, gravity and
''' liquids), then evaluated for any state of a body: the stepping solvers at the start of each step, the
''' event solver's integrated motions at each stage of their steps.
''' </summary>
Friend NotInheritable Class ForceField
    Private ReadOnly _gravity As Double
    Private ReadOnly _air As Double
    Private ReadOnly _liquids As Liquid()

    Friend Sub New(world As World)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        _gravity = world.Gravity
        _air = world.AirDensity
        _liquids = world.Liquids.ToArray()
    End Sub

    ''' <summary>Whether any force here acts on <paramref name="body"/> (a movable one) anywhere.</summary>
    Friend Function Acts(body As Shape) As Boolean
        Return body.LinearDrag > 0 OrElse (_air > 0 AndAlso body.DragCoefficient > 0) OrElse _liquids.Length > 0
    End Function

    ''' <summary>Whether some drag can act on <paramref name="body"/>: its own linear drag, air with its drag coefficient, or a liquid's drag.</summary>
    Friend Function CanDrag(body As Shape) As Boolean
        If body.LinearDrag > 0 OrElse (_air > 0 AndAlso body.DragCoefficient > 0) Then Return True
        For Each l In _liquids
            If l.LinearDrag > 0 OrElse l.DragCoefficient > 0 Then Return True
        Next
        Return False
    End Function

    ''' <summary>Whether the world has any liquid.</summary>
    Friend ReadOnly Property HasLiquids As Boolean
        Get
            Return _liquids.Length > 0
        End Get
    End Property

    ''' <summary>
    ''' The force on <paramref name="body"/> (N) with its reference point at <paramref name="position"/> (m)
    ''' moving at <paramref name="velocity"/> (m/s). <paramref name="dragPower"/> is the rate (W, ≥ 0) at which
    ''' the drag forces among it take energy away: −F_drag·v.
    ''' </summary>
    Friend Function Force(body As Shape, position As Vector, velocity As Vector, ByRef dragPower As Double) As Vector
        Dim resistance As Double, lift As Double
        Evaluate(body, position, velocity, resistance, lift)
        dragPower = resistance * velocity.LengthSquared
        Return New Vector(-resistance * velocity.X, lift - resistance * velocity.Y)
    End Function

    ''' <summary>
    ''' The two parts of the force: every drag here acts along −v, so together they are −c v with
    ''' <paramref name="resistance"/> c = b + ½ ρ C_d L |v| + Σ (fraction inside) (b_l + ½ ρ_l C_d L |v|) (N·s/m,
    ''' ≥ 0); and <paramref name="lift"/>, the buoyancy ρ_l g A_sub upwards summed over the liquids (N).
    ''' </summary>
    Friend Sub Evaluate(body As Shape, position As Vector, velocity As Vector, ByRef resistance As Double, ByRef lift As Double)
        Dim c = body.LinearDrag
        Dim speed = velocity.Length
        Dim width = -1.0 ' L, worked out once if some quadratic drag needs it
        If _air > 0 AndAlso body.DragCoefficient > 0 AndAlso speed > 0 Then
            width = QuadraticDrag.Width(body.Outline, velocity)
            c += 0.5 * _air * body.DragCoefficient * width * speed
        End If
        Dim up = 0.0
        For Each l In _liquids
            Dim part = SubmergedArea.Inside(body.Outline, position, l.Min, l.Max)
            If part.Area <= 0 Then Continue For
            up += Buoyancy.Force(l.Density, _gravity, part)
            Dim fraction = Math.Min(part.Area / body.Area, 1)
            Dim inLiquid = l.LinearDrag
            If l.DragCoefficient > 0 AndAlso speed > 0 Then
                If width < 0 Then width = QuadraticDrag.Width(body.Outline, velocity)
                inLiquid += 0.5 * l.Density * l.DragCoefficient * width * speed
            End If
            c += inLiquid * fraction
        Next
        resistance = c
        lift = up
    End Sub
End Class
