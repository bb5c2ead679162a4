Option Strict On

Namespace Checking
    ''' <summary>
    ''' Kinetic plus potential energy (Σ ½ m v² + m g y over every movable body, circle, box or polygon, at its
    ''' centre of mass, plus Σ ½ k x² over springs, J) may never grow when e ≤ 1: nothing in the model adds
    ''' energy. Two allowances, both far below a real leak:
    ''' <list type="bullet">
    ''' <item>Rounding: 1e-9 of the energy's scale (the sum of the magnitudes of every movable body's kinetic
    ''' and potential energy and every spring's stored energy at the start, so a scene whose total is near
    ''' zero, with walls off and bodies below y = 0, still has a scale). The scale counts what the total
    ''' counts: a scene of boxes and springs has as much rounding as one of balls. Each collision rounds each velocity to about 1e-16 relative; the engine's
    ''' own invariant tests see about 1e-12 of the energy over thousands of collisions. A real leak, such as
    ''' lifting a ball by a step's penetration without paying for it, is 1e-3 of that ball's energy.</item>
    ''' <item>The overlaps a scene may start with: the format accepts 1e-9 m, and pushing such an overlap
    ''' apart may lift a body by that much, once: m g · 1e-9 m for every movable body.</item>
    ''' <item>What a spring's energy can be read to: its ends' positions are rounded to a few parts in 10¹⁶ of the
    ''' coordinates (the container's size, W), so ½ k x² is known only to k x · 4ε W, with x at most √(2 E / k) (all
    ''' of the scale E in the spring): √(2 E k) · 4ε W for every spring. A 57 kN/m spring holding 10⁻¹³ J is read to
    ''' 2·10⁻¹⁹ J, above 10⁻⁹ of it.</item>
    ''' </list>
    ''' </summary>
    Friend NotInheritable Class EnergyBudget
        ''' <summary>Allowed growth, as a fraction of the energy's scale.</summary>
        Friend Const RelativeTolerance As Double = 0.000000001

        ''' <summary>The spacing of doubles near 1 (2⁻⁵²).</summary>
        Private Const Epsilon As Double = 2.220446049250313E-16

        Private ReadOnly _start As Double
        Private ReadOnly _allowed As Double

        ''' <summary>Takes the world's state now as the start.</summary>
        Friend Sub New(world As World)
            If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
            _start = Total(world)
            Dim scale = 0.0, lift = 0.0
            For Each b In world.Movables
                scale += b.KineticEnergy + b.Mass * world.Gravity * Math.Abs(b.CentreOfMass.Y)
                lift += b.Mass * world.Gravity * StateChecks.Tolerance
            Next
            For Each l In world.Links
                scale += l.StoredEnergy
            Next
            Dim reading = 0.0
            Dim size = Math.Max(1.0, Math.Max(world.Width, world.Height))
            For Each l In world.Links
                If l.Kind = LinkKind.Spring Then reading += Math.Sqrt(2 * scale * l.Stiffness) * 4 * Epsilon * size
            Next
            _allowed = RelativeTolerance * scale + lift + reading
        End Sub

        ''' <summary>The energy at the start, J.</summary>
        Friend ReadOnly Property Start As Double
            Get
                Return _start
            End Get
        End Property

        ''' <summary>How far above the start the energy may go, J.</summary>
        Friend ReadOnly Property Allowed As Double
            Get
                Return _allowed
            End Get
        End Property

        ''' <summary>Nothing, or a line saying by how much the energy grew beyond the allowance.</summary>
        Friend Function Check(world As World) As String
            Dim now = Total(world)
            If now <= _start + _allowed Then Return Nothing
            Return "energy grew from " & _start.ToString("R", Globalization.CultureInfo.InvariantCulture) & " J to " &
                now.ToString("R", Globalization.CultureInfo.InvariantCulture) & " J (+" & StateChecks.Brief(now - _start) &
                " J; allowed " & StateChecks.Brief(_allowed) & " J)"
        End Function

        ''' <summary>Kinetic plus potential energy of the movable bodies and springs, J, as the command line's summary gives it.</summary>
        Friend Shared Function Total(world As World) As Double
            Return world.KineticEnergy() + world.PotentialEnergy()
        End Function
    End Class
End Namespace
