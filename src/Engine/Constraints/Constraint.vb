Option Strict On

''' <summary>
''' One condition ψ = 0 that a group of bodies moving together keeps (docs/contact.md): a rod or a taut string
''' between two bodies or a body and a fixed point, or a lasting contact between two bodies or a body and a
''' fixed body or wall. Slots index a state array laid out per body as x, y, vx, vy (m, m/s), centres of mass.
''' <para>
''' Every shape has a unit direction u (m⁰) along which its force λ acts: +λu on body A, −λu on body B. The
''' conditions are written so that ψ̇ = u·(v_A − v_B) and ψ̈ = u·(a_A − a_B) + κ, where κ (m/s²) is the part that
''' the velocities alone make (the turning of the line between the two): so a force λ ≥ 0 always pushes A away
''' from B along u (a contact), or pulls A towards B (a string, for which u points from A to B).
''' </para>
''' <para>
''' For a contact, d = c_A − c_B − shift (c_B = 0 for a fixed body or a wall) is the difference of the two
''' bodies' reference points, and the contact is on one feature of their pair shape K (the Minkowski difference
''' of the outlines): an edge (<see cref="ConstraintShape.Plane"/>: its outward normal n and level h) or a
''' rounded corner (<see cref="ConstraintShape.Round"/>: its centre c and radius R; two balls are a corner of a
''' point). The feature holds while d stays in its region: along the edge, or within the corner's normal
''' cone; <see cref="Margin"/> measures how far inside it is.
''' </para>
''' </summary>
Friend NotInheritable Class Constraint
    Private Sub New(shape As ConstraintShape, a As Integer, b As Integer, point As Vector, length As Double, normal As Vector,
                    holds As Boolean)
        Me.Shape = shape
        Me.A = a
        Me.B = b
        Me.Point = point
        Me.Length = length
        Me.Normal = normal
        Me.Holds = holds
        Scale = length
    End Sub

    ''' <summary>A rod (<paramref name="holds"/>: it pushes and pulls) or a taut string (it only pulls) from slot a to slot b (−1: the fixed point <paramref name="anchor"/>, m), <paramref name="length"/> m long.</summary>
    Friend Shared Function Tie(a As Integer, b As Integer, anchor As Vector, length As Double, holds As Boolean) As Constraint
        Return New Constraint(ConstraintShape.Tie, a, b, anchor, length, Vector.Zero, holds)
    End Function

    ''' <summary>
    ''' A contact on a flat face: ψ = n·d − h with d = c_A − c_B − <paramref name="shift"/> (m). Bounded to the
    ''' edge from <paramref name="from"/> along <paramref name="along"/> for <paramref name="extent"/> m, or
    ''' unbounded (a wall) when <paramref name="extent"/> is +∞.
    ''' </summary>
    Friend Shared Function Plane(a As Integer, b As Integer, shift As Vector, normal As Vector, level As Double,
                                 from As Vector, along As Vector, extent As Double) As Constraint
        Dim c = New Constraint(ConstraintShape.Plane, a, b, shift, level, normal, False)
        c.From = from
        c.Along = along
        c.Extent = extent
        Return c
    End Function

    ''' <summary>
    ''' A contact on a round part: ψ = |d − <paramref name="centre"/>| − <paramref name="radius"/>. Bounded to the
    ''' corner's normal cone, between the end of the edge before it (direction <paramref name="before"/>) and the
    ''' start of the edge after it (<paramref name="after"/>); unbounded (two balls, a peg) when both are zero.
    ''' </summary>
    Friend Shared Function Round(a As Integer, b As Integer, shift As Vector, centre As Vector, radius As Double,
                                 before As Vector, after As Vector) As Constraint
        Dim c = New Constraint(ConstraintShape.Round, a, b, shift, radius, centre, False)
        c.From = before
        c.Along = after
        c.Extent = If(before = Vector.Zero AndAlso after = Vector.Zero, Double.PositiveInfinity, 0)
        Return c
    End Function

    ''' <summary>
    ''' A body held where it is along <paramref name="normal"/> by two ties in line (<see cref="TieLock"/>): ψ = n·c_A −
    ''' <paramref name="level"/> (m), kept at zero both ways. <paramref name="scale"/> (m) is the ties' size, the
    ''' length the drift is measured against; <paramref name="tie"/> the link it comes from.
    ''' </summary>
    Friend Shared Function Lock(a As Integer, normal As Vector, level As Double, scale As Double, tie As Object) As Constraint
        Dim c = New Constraint(ConstraintShape.Plane, a, -1, Vector.Zero, level, normal, True) With {
            .Extent = Double.PositiveInfinity, .Scale = scale, .Tag = tie, .IsLock = True}
        Return c
    End Function

    ''' <summary>Whether this is a <see cref="Lock"/>: no contact, no link, but two links' hold together.</summary>
    Friend Property IsLock As Boolean

    ''' <summary>The same constraint on other slots (a group's bodies numbered anew), with its tag and scale.</summary>
    Friend Function WithSlots(a As Integer, b As Integer) As Constraint
        Dim c = New Constraint(Shape, a, b, Point, Length, Normal, Holds) With {.From = From, .Along = Along, .Extent = Extent, .Tag = Tag, .Scale = Scale,
            .Friction = Friction, .StaticFriction = StaticFriction, .Sliding = Sliding, .IsLock = IsLock}
        Return c
    End Function

    ''' <summary>
    ''' A contact on a flat face that sticks (docs/contact.md, "Friction"): holds the position along the face,
    ''' t·d, where it is in <paramref name="state"/>, with a force of either sign, which Coulomb's law bounds by μs
    ''' times <paramref name="face"/>'s push (<see cref="StuckTo"/>).
    ''' </summary>
    Friend Shared Function Sticking(face As Constraint, state As Double()) As Constraint
        Dim t = face.Along
        Dim d = face.Difference(state)
        Dim c = New Constraint(ConstraintShape.Plane, face.A, face.B, face.Point, Vector.Dot(t, d), t, True) With {
            .Extent = Double.PositiveInfinity, .Tag = face.Tag, .Scale = face.Scale, .StuckTo = face}
        Return c
    End Function

    ''' <summary>μk of a contact on a flat face (0: frictionless).</summary>
    Friend Property Friction As Double

    ''' <summary>μs of a contact on a flat face.</summary>
    Friend Property StaticFriction As Double

    ''' <summary>
    ''' A contact with friction sliding: +1 when A slides along the face's direction relative to B, −1 against it, 0
    ''' when it does not slide (it sticks, or has no friction). Its force then leans back against the sliding:
    ''' λ (n − μk s t) on A.
    ''' </summary>
    Friend Property Sliding As Integer

    ''' <summary>For the tangential row of a contact that sticks: that contact's normal row; else Nothing.</summary>
    Friend Property StuckTo As Constraint

    ''' <summary>The direction its force acts along on A (unit for a frictionless row): u, leaning back by μk along the face when it slides.</summary>
    Friend Function ForceDirection(u As Vector) As Vector
        If Sliding = 0 Then Return u
        Return u - Along * (Friction * Sliding)
    End Function

    ''' <summary>A contact on a flat face: how fast A slides along it relative to B (m/s) at <paramref name="state"/>.</summary>
    Friend Function SlidingRate(state As Double()) As Double
        Return Vector.Dot(Along, RelativeVelocity(state))
    End Function

    ''' <summary>What it holds.</summary>
    Friend ReadOnly Property Shape As ConstraintShape

    ''' <summary>Body A's slot (the force acts +λu on it).</summary>
    Friend ReadOnly Property A As Integer

    ''' <summary>Body B's slot, or −1 for a fixed point, a fixed body or a wall.</summary>
    Friend ReadOnly Property B As Integer

    ''' <summary>A tie's fixed point when B is −1; a contact's shift (m).</summary>
    Friend ReadOnly Property Point As Vector

    ''' <summary>A tie's length, a face's level h, a round part's radius R (m).</summary>
    Friend ReadOnly Property Length As Double

    ''' <summary>A face's outward normal; a round part's centre (m).</summary>
    Friend ReadOnly Property Normal As Vector

    ''' <summary>Two-sided (a rod): its force may have either sign and ψ is held at 0 whatever it takes.</summary>
    Friend ReadOnly Property Holds As Boolean

    ''' <summary>A face: its first point (m). A corner: the direction of the edge before it.</summary>
    Friend Property From As Vector

    ''' <summary>A face: its unit direction. A corner: the direction of the edge after it.</summary>
    Friend Property Along As Vector

    ''' <summary>A face's length (m); +∞ for a wall or a corner with no bounds; 0 for a bounded corner.</summary>
    Friend Property Extent As Double

    ''' <summary>What this constraint stands for to its owner (a link, or a contact's identity).</summary>
    Friend Property Tag As Object

    ''' <summary>A length (m) its drift is measured against: a tie's length, a contact's bodies' size.</summary>
    Friend Property Scale As Double

    ''' <summary>Whether <see cref="Margin"/> can ever run out.</summary>
    Friend ReadOnly Property Bounded As Boolean
        Get
            Return Shape <> ConstraintShape.Tie AndAlso Not Double.IsPositiveInfinity(Extent)
        End Get
    End Property

    Private Shared Function Position(state As Double(), k As Integer) As Vector
        Return New Vector(state(4 * k), state(4 * k + 1))
    End Function

    Private Shared Function Velocity(state As Double(), k As Integer) As Vector
        Return New Vector(state(4 * k + 2), state(4 * k + 3))
    End Function

    ''' <summary>A contact's d = c_A − c_B − shift (m).</summary>
    Friend Function Difference(state As Double()) As Vector
        Dim d = Position(state, A) - Point
        If B >= 0 Then d -= Position(state, B)
        Return d
    End Function

    ''' <summary>The relative velocity v_A − v_B (m/s).</summary>
    Friend Function RelativeVelocity(state As Double()) As Vector
        Dim w = Velocity(state, A)
        If B >= 0 Then w -= Velocity(state, B)
        Return w
    End Function

    ''' <summary>
    ''' At <paramref name="state"/>: the direction u, ψ (m), ψ̇ (m/s) and κ (m/s²), so that ψ̈ = u·(a_A − a_B) + κ.
    ''' </summary>
    Friend Sub Measure(state As Double(), ByRef u As Vector, ByRef value As Double, ByRef rate As Double, ByRef curvature As Double)
        Select Case Shape
            Case ConstraintShape.Tie
                Dim pb = If(B >= 0, Position(state, B), Point)
                Dim r = pb - Position(state, A)
                Dim d = r.Length
                u = r / d
                Dim w = If(B >= 0, Velocity(state, B), Vector.Zero) - Velocity(state, A)
                Dim along = Vector.Dot(u, w)
                value = Length - d
                rate = -along
                curvature = -(w.LengthSquared - along * along) / d
            Case ConstraintShape.Plane
                u = Normal
                value = Vector.Dot(Normal, Difference(state)) - Length
                rate = Vector.Dot(Normal, RelativeVelocity(state))
                curvature = 0
            Case Else
                Dim r = Difference(state) - Normal
                Dim rho = r.Length
                u = r / rho
                Dim w = RelativeVelocity(state)
                Dim along = Vector.Dot(u, w)
                value = rho - Length
                rate = along
                curvature = (w.LengthSquared - along * along) / rho
        End Select
    End Sub

    ''' <summary>The state array (per body: centre of mass x, y and velocity, m and m/s) of <paramref name="bodies"/> as they are now.</summary>
    Friend Shared Function StateOf(bodies As IReadOnlyList(Of Shape)) As Double()
        Dim y(4 * bodies.Count - 1) As Double
        For k = 0 To bodies.Count - 1
            Dim c = bodies(k).CentreOfMass
            y(4 * k) = c.X
            y(4 * k + 1) = c.Y
            y(4 * k + 2) = bodies(k).Velocity.X
            y(4 * k + 3) = bodies(k).Velocity.Y
        Next
        Return y
    End Function

    ''' <summary>The direction u now, for the slots' <paramref name="bodies"/> as they are.</summary>
    Friend Function UnitAt(bodies As IReadOnlyList(Of Shape)) As Vector
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        Measure(StateOf(bodies), u, value, rate, curvature)
        Return u
    End Function

    ''' <summary>
    ''' How far (m) a contact's d is inside its feature's region at <paramref name="state"/>: along a face, the
    ''' distance to its nearer end; at a corner, how far past the edge before it and short of the edge after it.
    ''' Negative once it has left; +∞ where there is no bound.
    ''' </summary>
    Friend Function Margin(state As Double()) As Double
        Dim first As Double, second As Double
        EndMargins(state, first, second)
        Return Math.Min(first, second)
    End Function

    ''' <summary>
    ''' The two parts of <see cref="Margin"/>, one for each end of the feature's region (m): along a face, how far d
    ''' is past its first vertex and short of its last; at a corner, how far past the edge before it and short of the
    ''' edge after it. +∞ both where there is no bound. A contact that starts at one end moving onto the feature
    ''' leaves it, if at all, by the other end: the two are watched apart.
    ''' </summary>
    Friend Sub EndMargins(state As Double(), ByRef first As Double, ByRef second As Double)
        If Not Bounded Then
            first = Double.PositiveInfinity
            second = Double.PositiveInfinity
            Return
        End If
        Dim d = Difference(state)
        If Shape = ConstraintShape.Plane Then
            Dim s = Vector.Dot(d - From, Along)
            first = s
            second = Extent - s
            Return
        End If
        Dim r = d - Normal
        first = Vector.Dot(r, From)
        second = -Vector.Dot(r, Along)
    End Sub
End Class
