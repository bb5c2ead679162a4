Option Strict On

''' <summary>The totals of the movable bodies at one moment: one row of the graph series.</summary>
Public Structure SeriesSample
    ''' <summary>Simulated time, s.</summary>
    Public Property Time As Double
    ''' <summary>Σ ½ m v², J.</summary>
    Public Property Kinetic As Double
    ''' <summary>Σ m g y plus the springs' stored energy, J.</summary>
    Public Property Potential As Double
    ''' <summary>Σ m v, kg·m/s.</summary>
    Public Property Momentum As Vector
    ''' <summary>The movable bodies' centre of mass, m (NaN when there are none).</summary>
    Public Property CentreOfMass As Vector

    ''' <summary>Kinetic plus potential, J.</summary>
    Public ReadOnly Property Total As Double
        Get
            Return Kinetic + Potential
        End Get
    End Property

    ''' <summary>The totals of <paramref name="world"/> now.</summary>
    Public Shared Function Take(world As World) As SeriesSample
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim com = If(world.Movables.Count = 0, New Vector(Double.NaN, Double.NaN), world.CentreOfMass())
        Return New SeriesSample With {.Time = world.Time, .Kinetic = world.KineticEnergy(), .Potential = world.PotentialEnergy(),
                                      .Momentum = world.Momentum(), .CentreOfMass = com}
    End Function
End Structure
