Option Strict On

''' <summary>
''' A world read as a gas at one moment: how many movable bodies, their temperature, masses and
''' speeds, and the container's free area and perimeter.
''' </summary>
Public NotInheritable Class GasState
    Private Sub New()
    End Sub

    ''' <summary>Simulated time, s.</summary>
    Public ReadOnly Property Time As Double
    ''' <summary>Movable bodies N.</summary>
    Public ReadOnly Property Count As Integer
    ''' <summary>kT = mean kinetic energy per movable body, J (see <see cref="GasLaw.Temperature"/>).</summary>
    Public ReadOnly Property KT As Double
    ''' <summary>Each movable body's mass, kg.</summary>
    Public ReadOnly Property Masses As IReadOnlyList(Of Double)
    ''' <summary>Each movable body's speed, m/s.</summary>
    Public ReadOnly Property Speeds As IReadOnlyList(Of Double)
    ''' <summary>The container's area less the fixed bodies' (m²): the area A the gas has.</summary>
    Public ReadOnly Property FreeArea As Double
    ''' <summary>The container's perimeter 2(w + h), m: the walls the pressure is measured on.</summary>
    Public ReadOnly Property Perimeter As Double
    ''' <summary>The movable bodies' area over <see cref="FreeArea"/>: the packing fraction η.</summary>
    Public ReadOnly Property PackingFraction As Double

    ''' <summary>N k T / A, N/m.</summary>
    Public ReadOnly Property IdealPressure As Double
        Get
            Return GasLaw.IdealPressure(Count, KT, FreeArea)
        End Get
    End Property

    ''' <summary>The hard-disc estimate Z(η) N k T / A, N/m (see <see cref="GasLaw.HardDiscFactor"/>).</summary>
    Public ReadOnly Property HardDiscPressure As Double
        Get
            Return GasLaw.HardDiscFactor(PackingFraction) * IdealPressure
        End Get
    End Property

    ''' <summary>Reads <paramref name="world"/> now.</summary>
    Public Shared Function Read(world As World) As GasState
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim masses As New List(Of Double)(world.Movables.Count)
        Dim speeds As New List(Of Double)(world.Movables.Count)
        Dim kinetic = 0.0, bodyArea = 0.0
        For Each b In world.Movables
            masses.Add(b.Mass)
            speeds.Add(b.Velocity.Length)
            kinetic += b.KineticEnergy
            bodyArea += b.Area
        Next
        Dim fixedArea = world.Bodies.Where(Function(b) b.IsFixed).Sum(Function(b) b.Area)
        Dim free = Math.Max(0.0, world.Width * world.Height - fixedArea)
        Return New GasState With {
            ._Time = world.Time, ._Count = masses.Count, ._KT = GasLaw.Temperature(kinetic, masses.Count),
            ._Masses = masses, ._Speeds = speeds, ._FreeArea = free, ._Perimeter = 2 * (world.Width + world.Height),
            ._PackingFraction = If(free > 0, bodyArea / free, Double.NaN)}
    End Function
End Class
