Option Strict On

''' <summary>
''' Bodies that touch only flat faces (walls, the edges of their pair shapes) and have no links, pressed on by
''' gravity alone (docs/contact.md, "Flat contacts"): the contacts' directions never turn and nothing depends on
''' the velocities, so the contact forces found at the start hold as long as the contacts do, and every body
''' moves with a constant acceleration, p = p₀ + v₀τ + ½aτ², exactly. A box on a table (a = 0), a stack of boxes,
''' a box sliding down a ramp at g sin θ (g (sin θ − μk cos θ) on a rough one), a ball resting in a V. The forces are
''' constant, so no contact lifts off; the motion ends where a contact runs off the end of its face (a quadratic's
''' root), or where one sliding with friction stops (a linear one), or never.
''' </summary>
Friend NotInheritable Class UniformMotion
    Inherits LinkedMotion

    ' An acceleration within this fraction of g of zero is zero: what is left of the balance of the weight and
    ' the contact forces after rounding, which would otherwise move a body at rest by ½ × 10⁻¹⁶ g τ².
    Friend Const RestFraction As Double = 0.000000000001
    ' Nor is one within this fraction of what the contact forces on the body give it: pressed by a heavy body, a light
    ' one's forces are 10¹¹ times its weight, and their balance leaves 10⁻¹⁶ of that (a 1.3 mg triangle under a 1.5 t
    ' polygon kept 1.5·10⁻⁵ m/s² downwards and sank 3 nm into the floor in 20 ms).
    Private Const PressRounding As Double = 0.0000000000001

    Private ReadOnly _p0 As Vector()
    Private ReadOnly _v0 As Vector()
    Private ReadOnly _a As Vector()
    Private ReadOnly _contacts As Constraint()
    Private ReadOnly _leaves As Double = Double.PositiveInfinity
    Private ReadOnly _forces As Double()
    ' A group at rest with links: the rods and taut strings it holds, their tensions (N), and every other link.
    Private ReadOnly _held As Link() = Array.Empty(Of Link)()
    Private ReadOnly _tensions As Double() = Array.Empty(Of Double)()
    Private ReadOnly _slack As Link() = Array.Empty(Of Link)()
    ' The rows by which two ties in line hold a body where it is (TieLock).
    Private ReadOnly _locks As Constraint() = Array.Empty(Of Constraint)()

    ''' <summary>
    ''' A group at rest: every body still and every force balanced (a box on a table held by a spring pulling less
    ''' than its weight, a bob hanging on a string against a wall). Nothing moves, so nothing changes, links and
    ''' all: its rods and taut strings <paramref name="held"/> keep <paramref name="tensions"/> (N), the other
    ''' <paramref name="slack"/> ones none; <paramref name="locks"/> hold bodies where two ties in line keep them.
    ''' </summary>
    Friend Sub New(bodies As Shape(), contacts As Constraint(), held As Link(), tensions As Double(), slack As Link(), locks As Constraint(), startTime As Double)
        MyBase.New(bodies, startTime)
        _contacts = contacts
        _locks = locks
        _held = held
        _tensions = tensions
        _slack = slack
        _forces = New Double(contacts.Length - 1) {}
        _p0 = bodies.Select(Function(b) b.CentreOfMass).ToArray()
        _v0 = New Vector(bodies.Length - 1) {}
        _a = New Vector(bodies.Length - 1) {}
    End Sub

    ''' <summary>The <paramref name="bodies"/> from their states now (already on the <paramref name="contacts"/>), under <paramref name="gravity"/> (m/s²).</summary>
    Friend Sub New(bodies As Shape(), contacts As Constraint(), startTime As Double, gravity As Double)
        MyBase.New(bodies, startTime)
        _contacts = contacts
        Dim n = bodies.Length
        Dim y = Constraint.StateOf(bodies)
        Dim accel(4 * n - 1) As Double
        For k = 0 To n - 1
            accel(4 * k + 3) = -gravity
        Next
        _forces = New ConstraintSet(contacts, bodies.Select(Function(b) b.InverseMass).ToArray()).Tensions(y, accel)
        _p0 = New Vector(n - 1) {}
        _v0 = New Vector(n - 1) {}
        _a = New Vector(n - 1) {}
        ' What the contact forces give each body, m/s²: the scale of the rounding in its acceleration.
        Dim pressed(n - 1) As Double
        For ci = 0 To contacts.Length - 1
            Dim c = contacts(ci)
            pressed(c.A) += Math.Abs(_forces(ci)) * bodies(c.A).InverseMass
            If c.B >= 0 Then pressed(c.B) += Math.Abs(_forces(ci)) * bodies(c.B).InverseMass
        Next
        For k = 0 To n - 1
            _p0(k) = New Vector(y(4 * k), y(4 * k + 1))
            _v0(k) = New Vector(y(4 * k + 2), y(4 * k + 3))
            Dim ax = accel(4 * k + 2), ay = accel(4 * k + 3)
            Dim zero = Math.Max(RestFraction * gravity, PressRounding * pressed(k))
            _a(k) = New Vector(If(Math.Abs(ax) <= zero, 0, ax), If(Math.Abs(ay) <= zero, 0, ay))
        Next
        For Each c In contacts
            ' A contact sliding with friction slows at a constant rate: it stops where its sliding speed reaches zero.
            If c.Sliding <> 0 Then
                Dim rate = Vector.Dot(_v0(c.A) - If(c.B >= 0, _v0(c.B), Vector.Zero), c.Along)
                Dim slowing = Vector.Dot(_a(c.A) - If(c.B >= 0, _a(c.B), Vector.Zero), c.Along)
                If rate * slowing < 0 Then _leaves = Math.Min(_leaves, startTime - rate / slowing)
            End If
            If Not c.Bounded Then Continue For
            ' Along the face, s(τ) = s₀ + ṡτ + ½s̈τ² from the relative motion of the two bodies.
            Dim d = _p0(c.A) - c.Point - If(c.B >= 0, _p0(c.B), Vector.Zero)
            Dim w = _v0(c.A) - If(c.B >= 0, _v0(c.B), Vector.Zero)
            Dim q = _a(c.A) - If(c.B >= 0, _a(c.B), Vector.Zero)
            Dim s0 = Vector.Dot(d - c.From, c.Along)
            _leaves = Math.Min(_leaves, startTime + RestingFaces.TimeOnFace(s0, Vector.Dot(w, c.Along), Vector.Dot(q, c.Along), c.Extent))
        Next
    End Sub

    ''' <summary>Whether nothing moves at all: every body still, with no acceleration.</summary>
    Friend ReadOnly Property AtRest As Boolean
        Get
            For k = 0 To _v0.Length - 1
                If _v0(k) <> Vector.Zero OrElse _a(k) <> Vector.Zero Then Return False
            Next
            Return True
        End Get
    End Property

    ''' <summary>Body k's constant acceleration, m/s².</summary>
    Friend ReadOnly Property Acceleration(k As Integer) As Vector
        Get
            Return _a(k)
        End Get
    End Property

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim tau = time - StartTime
        Dim p = _p0(k), v = _v0(k), a = _a(k)
        position = New Vector(p.X + (v.X + 0.5 * a.X * tau) * tau, p.Y + (v.Y + 0.5 * a.Y * tau) * tau)
        velocity = New Vector(v.X + a.X * tau, v.Y + a.Y * tau)
    End Sub

    Friend Overrides Function Parabola(k As Integer, time As Double, ByRef position As Vector, ByRef velocity As Vector, ByRef acceleration As Vector) As Boolean
        StateAt(time, k, position, velocity)
        acceleration = _a(k)
        Return True
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        ' |v| is convex in time with a constant acceleration: its largest value is at an end.
        Dim p As Vector, a As Vector, b As Vector
        StateAt(t0, k, p, a)
        StateAt(t1, k, p, b)
        Return Math.Max(a.Length, b.Length)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _a(k).Length
    End Function

    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _leaves
        End Get
    End Property

    Friend Overrides ReadOnly Property HeldLinks As Link()
        Get
            Return _held
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        For i = 0 To _held.Length - 1
            _held(i).SetTension(_tensions(i))
        Next
        For Each l In _slack
            If l.Kind <> LinkKind.Spring Then l.SetTension(0)
        Next
    End Sub

    Friend Overrides ReadOnly Property HeldContacts As Constraint()
        Get
            Return _contacts
        End Get
    End Property

    Friend Overrides ReadOnly Property HeldLocks As Constraint()
        Get
            Return _locks
        End Get
    End Property

    ''' <summary>The contact forces (N), in the order of <see cref="HeldContacts"/>: constant while this motion lasts.</summary>
    Friend ReadOnly Property Forces As Double()
        Get
            Return _forces
        End Get
    End Property
End Class
