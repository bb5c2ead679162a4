Option Strict On

''' <summary>
''' The drag and buoyancy term of an integrated group's equations of motion (springs, chains): each body's
''' <see cref="ForceField"/> force ÷ its mass, added to the acceleration of a state laid out as the integrators
''' lay it out (per body: centre x, y, then vx, vy).
''' </summary>
Friend Module BodyForceTerm
    ''' <summary>Adds F/m of every body that <paramref name="forces"/> acts on to <paramref name="d"/>, dy/dt of state <paramref name="y"/>.</summary>
    Friend Sub Add(forces As ForceField, bodies As Shape(), y As Double(), d As Double())
        For k = 0 To bodies.Length - 1
            Dim body = bodies(k)
            If Not forces.Acts(body) Then Continue For
            Dim power As Double
            ' The forces are worked out where the outline is: the reference point is the centre less the centroid's offset.
            Dim f = forces.Force(body, New Vector(y(4 * k), y(4 * k + 1)) - body.Outline.Centroid, New Vector(y(4 * k + 2), y(4 * k + 3)), power)
            d(4 * k + 2) += f.X * body.InverseMass
            d(4 * k + 3) += f.Y * body.InverseMass
        Next
    End Sub
End Module
