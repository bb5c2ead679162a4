Option Strict On

''' <summary>
''' The movable bodies taken together: total mass, centre of mass, total momentum and the velocity
''' of the centre of mass. Fixed bodies have no momentum (their mass is infinite and they never
''' move), so they are left out, as in <see cref="World.Momentum"/>.
''' </summary>
Public Structure MomentumSummary
    ''' <summary>Σm over movable bodies, kg (0 when there are none).</summary>
    Public ReadOnly Property Mass As Double
    ''' <summary>Σm·x / Σm, m (meaningless when <see cref="Mass"/> is 0).</summary>
    Public ReadOnly Property CentreOfMass As Vector
    ''' <summary>Σp = Σm·v, kg·m/s.</summary>
    Public ReadOnly Property Momentum As Vector

    Private Sub New(mass As Double, centre As Vector, momentum As Vector)
        Me.Mass = mass
        Me.CentreOfMass = centre
        Me.Momentum = momentum
    End Sub

    ''' <summary>True when there is at least one movable body (so the centre of mass exists).</summary>
    Public ReadOnly Property HasBodies As Boolean
        Get
            Return Mass > 0
        End Get
    End Property

    ''' <summary>The velocity of the centre of mass, Σp / Σm, m/s.</summary>
    Public ReadOnly Property Velocity As Vector
        Get
            Return If(HasBodies, Momentum / Mass, Vector.Zero)
        End Get
    End Property

    ''' <summary>The movable bodies of <paramref name="world"/> now.</summary>
    Public Shared Function Measure(world As World) As MomentumSummary
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim m = 0.0, mx = 0.0, my = 0.0, px = 0.0, py = 0.0
        For Each b In world.Movables
            Dim c = b.CentreOfMass
            m += b.Mass
            mx += b.Mass * c.X
            my += b.Mass * c.Y
            px += b.Mass * b.Velocity.X
            py += b.Mass * b.Velocity.Y
        Next
        If Not (m > 0) Then Return New MomentumSummary(0, Vector.Zero, Vector.Zero)
        Return New MomentumSummary(m, New Vector(mx / m, my / m), New Vector(px, py))
    End Function
End Structure
