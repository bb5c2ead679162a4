Option Strict On

''' <summary>
''' How a slow body leaves a slope it would otherwise chatter on (docs/event-driven.md §6): with at
''' least a minimum speed along the normal, so that it hops down the slope in finitely many events, and
''' with no more energy than it had before the contact. Such hops stand for sliding, which loses nothing:
''' a hop that lands at the minimum speed leaves at it again, its speed along the slope kept. One that
''' lands slower (the slope curves away beneath it) pays the difference from its speed along the slope.
''' One too slow for that (a body at rest on a slope) first moves down the slope's tangent line by the
''' height that pays for the hop, m g h = ½ m (u² − v²): a convex support lies wholly on one side of its
''' tangent, so that move never takes the body into the support.
''' </summary>
Friend Module SlopeHop
    ''' <summary>
    ''' The velocity (m/s) a body leaves the slope with, and in <paramref name="shift"/> how far (m) it
    ''' moves down the tangent first (zero unless its speed before the contact cannot pay for the hop).
    ''' Its normal speed is at least <paramref name="minimum"/> (less only when the move is capped), its
    ''' speed along the slope never grows, and its kinetic energy is at most what it had before the
    ''' contact plus g times the height lost (to rounding).
    ''' </summary>
    ''' <param name="before">velocity relative to the support before the contact, m/s</param>
    ''' <param name="after">velocity relative to the support after the contact's impulse, m/s</param>
    ''' <param name="normal">unit contact normal, pointing from the support towards the body</param>
    ''' <param name="minimum">the normal speed the body should leave with at least, m/s</param>
    ''' <param name="gravity">g, m/s² (towards −y)</param>
    ''' <param name="maxShift">the furthest it may move down the tangent, m (0: it may not move)</param>
    ''' <param name="shift">the move down the tangent, m</param>
    Friend Function Depart(before As Vector, after As Vector, normal As Vector, minimum As Double, gravity As Double,
                           maxShift As Double, ByRef shift As Vector) As Vector
        shift = Vector.Zero
        Dim vn = Vector.Dot(after, normal)
        If vn >= minimum Then Return after
        Dim tangential = after - normal * vn
        Dim t2 = tangential.LengthSquared
        Dim budget2 = before.LengthSquared ' twice the kinetic energy per kg it came with
        Dim minimum2 = minimum * minimum
        If budget2 >= minimum2 Then
            ' Normal part u; along the slope as it was, but no faster than the rest of the budget allows.
            If t2 = 0 Then Return normal * minimum
            Return normal * minimum + tangential * Math.Sqrt(Math.Min(1.0, (budget2 - minimum2) / t2))
        End If
        ' Too slow: the hop's energy comes from height, lost by sliding down the tangent line first.
        Dim slope = Math.Abs(normal.X) ' height lost per metre along the tangent
        Dim distance = 0.0
        If slope > 0 AndAlso gravity > 0 AndAlso maxShift > 0 Then distance = Math.Min((minimum2 - budget2) / (2 * gravity * slope), maxShift)
        If distance > 0 Then shift = New Vector(normal.Y, -normal.X) * (Math.Sign(normal.X) * distance)
        Return normal * Math.Sqrt(budget2 + 2 * gravity * slope * distance)
    End Function
End Module
