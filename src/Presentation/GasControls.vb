Option Strict On

''' <summary>
''' The gas controls, as PhET's Gas Properties has them: heat and cool (every speed scaled, so the
''' temperature, the mean kinetic energy kT, goes up or down by a known factor), and balls added or
''' removed, new ones at the gas's own temperature. Each is an edit: Undo takes it back.
''' </summary>
Friend NotInheritable Class GasControls
    ''' <summary>What one press of Heat multiplies the temperature (the mean kinetic energy) by; Cool divides by it.</summary>
    Public Const HeatFactor As Double = 1.25
    ''' <summary>Balls one press of Add or Remove adds or removes.</summary>
    Public Const BallsPerPress As Integer = 10
    ''' <summary>The temperature new balls get in a gas that has none (every ball at rest), J: a ball of 1 kg at about 1 m/s.</summary>
    Public Const RestingKT As Double = 0.5
    ''' <summary>Random places tried for each new ball before giving up on it.</summary>
    Private Const Tries As Integer = 200

    Private ReadOnly _stage As Stage
    Private ReadOnly _history As EditHistory
    Private ReadOnly _random As Random

    Public Sub New(stage As Stage, history As EditHistory, seed As Integer)
        _stage = stage
        _history = history
        _random = New Random(seed)
    End Sub

    ''' <summary>The gas's temperature now: the mean kinetic energy of its moving bodies, kT, J (2D: two degrees of freedom, ½kT each).</summary>
    Public ReadOnly Property KT As Double
        Get
            Return GasState.Read(_stage.World).KT
        End Get
    End Property

    ''' <summary>Heats (<paramref name="warmer"/>) or cools the gas: every movable body's speed × √<see cref="HeatFactor"/> (or ÷), so kT × or ÷ <see cref="HeatFactor"/>.</summary>
    Public Sub Heat(warmer As Boolean)
        Dim movables = _stage.World.Movables.ToList()
        If movables.Count = 0 Then
            _stage.ShowMessage("There is nothing to " & If(warmer, "heat", "cool") & ": no body moves here. Add balls first.")
            Return
        End If
        Dim before = _history.Capture()
        Dim kt0 = KT
        Dim factor = Math.Sqrt(If(warmer, HeatFactor, 1 / HeatFactor))
        For Each b In movables
            _stage.World.SetVelocity(b, b.Velocity * factor)
        Next
        Dim kt1 = KT
        _history.Commit(If(warmer, "heating", "cooling"), before)
        _stage.Emit(If(warmer, "heat", "cool") & " kT " & Units.Num(kt0, 6) & " to " & Units.Num(kt1, 6) & " J")
        _stage.ShowMessage(If(warmer, "Heated", "Cooled") & ": the temperature, kT = mean KE, went from " & Units.Quantity(kt0, "J") & " to " & Units.Quantity(kt1, "J") &
                           " (every speed × " & Units.Sig(factor) & ").")
        _stage.TakeSnapshot()
    End Sub

    ''' <summary>
    ''' Adds <paramref name="count"/> balls like the gas's (the radius and mass of its commonest
    ''' ball, else the typed ones) at free places, each moving in a random direction with a random
    ''' velocity of the gas's temperature (each component normal, variance kT/m): the gas's kT stays
    ''' about as it was. Where there is no room for them all, as many as fit are added, and the message says so.
    ''' </summary>
    Public Sub AddBalls(count As Integer)
        Dim w = _stage.World
        Dim model = w.Circles.Where(Function(c) Not c.IsFixed).GroupBy(Function(c) (c.Radius, c.Mass)).OrderByDescending(Function(g) g.Count()).Select(Function(g) g.First()).ToList()
        Dim radius As Double, mass As Double, colour As String = Nothing
        If model.Count > 0 Then
            radius = model(0).Radius
            mass = model(0).Mass
            colour = model(0).Color
        Else
            Dim r = NumberInput.ReadPositive(_stage.Inputs.RadiusText, "radius (m)", InputLimits.MaxRadius, InputLimits.MinRadius)
            Dim m = NumberInput.ReadPositive(_stage.Inputs.MassText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass)
            If Not r.IsValid OrElse Not m.IsValid Then
                _stage.ShowMessage(InputLimits.CircleMessage & " " & Stage.Problems(r, m))
                Return
            End If
            radius = r.Value
            mass = m.Value
        End If
        Dim temperature = If(KT > 0, KT, RestingKT)
        Dim before = _history.Capture()
        Dim added = 0
        For k = 1 To count
            Dim ball = FreeBall(w, radius, mass, temperature)
            If ball Is Nothing Then Exit For
            w.Add(ball)
            ball.Color = If(String.IsNullOrEmpty(colour), BodyColours.ForId(ball.Id), colour)
            added += 1
        Next
        If added = 0 Then
            _stage.ShowMessage("There is no room for another ball of radius " & Units.Quantity(radius, "m") & " in the container.")
            Return
        End If
        _history.Commit(added & " balls added", before)
        _stage.Emit("added " & added & " balls, kT " & Units.Num(KT, 6) & " J")
        _stage.ShowMessage("Added " & added & " balls at the gas's temperature, kT = " & Units.Quantity(temperature, "J") & "; now " & w.Movables.Count & " moving bodies" &
                           If(added < count, " (there was room for only " & added & ")", "") & ".")
        _stage.TakeSnapshot()
    End Sub

    ''' <summary>A ball of the given size at a random free place, with a random velocity of temperature <paramref name="kt"/> (J); Nothing when no place is found.</summary>
    Private Function FreeBall(w As World, radius As Double, mass As Double, kt As Double) As Circle
        Dim spread = Math.Sqrt(kt / mass) ' m/s: each component's standard deviation
        For attempt = 1 To Tries
            Dim at As New Vector(radius + _random.NextDouble() * (w.Width - 2 * radius), radius + _random.NextDouble() * (w.Height - 2 * radius))
            Dim v As New Vector(spread * Normal(), spread * Normal())
            Dim ball As New Circle(at, radius, mass, v)
            If Placement.IsFree(w, ball, Vector.Zero) Then Return ball
        Next
        Return Nothing
    End Function

    ''' <summary>A standard normal number (Box–Muller).</summary>
    Private Function Normal() As Double
        Dim u1 = 1.0 - _random.NextDouble()
        Dim u2 = _random.NextDouble()
        Return Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2.0 * Math.PI * u2)
    End Function

    ''' <summary>Removes <paramref name="count"/> moving balls, chosen at random (the rest keep their speeds, so the temperature stays about the same).</summary>
    Public Sub RemoveBalls(count As Integer)
        Dim w = _stage.World
        Dim balls = w.Circles.Where(Function(c) Not c.IsFixed AndAlso w.DraggedBody IsNot c).Cast(Of Shape)().ToList()
        If balls.Count = 0 Then
            _stage.ShowMessage("There is no moving ball to remove.")
            Return
        End If
        Dim before = _history.Capture()
        Dim removed = 0
        For k = 1 To Math.Min(count, balls.Count)
            Dim i = _random.Next(balls.Count)
            w.Remove(balls(i))
            balls.RemoveAt(i)
            removed += 1
        Next
        _history.Commit(removed & " balls removed", before)
        _stage.Emit("removed " & removed & " balls")
        _stage.ShowMessage("Removed " & removed & " balls; now " & w.Movables.Count & " moving bodies, kT = " & Units.Quantity(KT, "J") & ".")
        _stage.TakeSnapshot()
    End Sub
End Class
