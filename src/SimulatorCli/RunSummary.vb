Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Text
Imports System.Text.Json

''' <summary>What run prints at the end: as text for a person, or as one JSON object for a script.</summary>
Friend NotInheritable Class RunSummary
    Private ReadOnly _scene As String
    Private ReadOnly _bodies As Integer
    Private ReadOnly _movable As Integer
    Private ReadOnly _solver As String
    Private ReadOnly _dt As Double?
    Private ReadOnly _simulated As Double
    Private ReadOnly _wall As Double
    Private ReadOnly _collisions As Long
    Private ReadOnly _kinetic As Double
    Private ReadOnly _potential As Double
    Private ReadOnly _momentum As Vector
    Private ReadOnly _states As String
    Private ReadOnly _events As String
    Private ReadOnly _series As String
    Private ReadOnly _warning As String

    ''' <param name="wallSeconds">wall-clock time of the simulation loop, s</param>
    ''' <param name="warning">Nothing, or the sentence naming a spring too stiff for the stepping solver's step (<see cref="RunCommand.StabilityWarning"/>)</param>
    Friend Sub New(o As RunOptions, world As World, movable As Integer, wallSeconds As Double, warning As String)
        _scene = o.ScenePath
        _bodies = world.Bodies.Count
        _movable = movable
        _solver = world.Solver.Name
        _dt = world.Solver.TimeStep
        _simulated = world.Time
        _wall = wallSeconds
        _collisions = world.CollisionCount
        _kinetic = world.KineticEnergy()
        _potential = Totals.PotentialEnergy(world)
        _momentum = world.Momentum()
        _states = o.StatesPath
        _events = o.EventsPath
        _series = o.SeriesPath
        _warning = warning
    End Sub

    ''' <summary>Collisions per wall-clock second; Nothing when the run took no measurable time.</summary>
    Private ReadOnly Property EventsPerSecond As Double?
        Get
            If _wall > 0 Then Return _collisions / _wall
            Return Nothing
        End Get
    End Property

    Friend Function ToText() As String
        Dim inv = CultureInfo.InvariantCulture
        Dim lines As New List(Of String) From {
            "scene             " & _scene & " (" & _bodies.ToString(inv) & " bodies, " & _movable.ToString(inv) & " movable)",
            "solver            " & _solver & If(_dt.HasValue, ", dt = " & _dt.Value.ToString("R", inv) & " s", ""),
            "simulated         " & _simulated.ToString("R", inv) & " s",
            "wall-clock        " & _wall.ToString("0.000", inv) & " s",
            "collisions        " & _collisions.ToString(inv) &
                If(EventsPerSecond.HasValue, " (" & EventsPerSecond.Value.ToString("0.#", inv) & " per wall-clock second)", ""),
            "kinetic energy    " & _kinetic.ToString("R", inv) & " J",
            "potential energy  " & _potential.ToString("R", inv) & " J (m g y of each movable body's centre of mass)",
            "total energy      " & (_kinetic + _potential).ToString("R", inv) & " J",
            "momentum          (" & _momentum.X.ToString("R", inv) & ", " & _momentum.Y.ToString("R", inv) & ") kg m/s"}
        If _states IsNot Nothing Then lines.Add("states CSV        " & _states)
        If _events IsNot Nothing Then lines.Add("collisions CSV    " & _events)
        If _series IsNot Nothing Then lines.Add("totals CSV        " & _series)
        If _warning IsNot Nothing Then lines.Add("warning           " & _warning)
        Return String.Join(vbLf, lines)
    End Function

    ''' <summary>
    ''' One JSON object on one line (cli.md's fields, plus scene, bodies, movable, energy_total, the output files,
    ''' and warning: null, or the sentence naming a spring too stiff for the stepping solver's step).
    ''' </summary>
    Friend Function ToJson() As String
        Using stream As New MemoryStream()
            Using w As New Utf8JsonWriter(stream)
                w.WriteStartObject()
                w.WriteString("scene", _scene)
                w.WriteNumber("bodies", _bodies)
                w.WriteNumber("movable", _movable)
                w.WriteString("solver", _solver)
                w.WritePropertyName("dt")
                WriteNumberOrNull(w, _dt)
                WriteNumber(w, "simulated_s", _simulated)
                WriteNumber(w, "wall_s", _wall)
                w.WriteNumber("collisions", _collisions)
                w.WritePropertyName("events_per_s")
                WriteNumberOrNull(w, EventsPerSecond)
                WriteNumber(w, "kinetic_energy", _kinetic)
                WriteNumber(w, "potential_energy", _potential)
                WriteNumber(w, "energy_total", _kinetic + _potential)
                w.WriteStartArray("momentum")
                WriteNumberOrNull(w, _momentum.X)
                WriteNumberOrNull(w, _momentum.Y)
                w.WriteEndArray()
                w.WriteString("states", _states)
                w.WriteString("events", _events)
                w.WriteString("series", _series)
                w.WriteString("warning", _warning)
                w.WriteEndObject()
            End Using
            Return Encoding.UTF8.GetString(stream.ToArray())
        End Using
    End Function

    Private Shared Sub WriteNumber(w As Utf8JsonWriter, name As String, value As Double)
        w.WritePropertyName(name)
        WriteNumberOrNull(w, value)
    End Sub

    ''' <summary>JSON has no NaN or ∞: a blown-up run says null rather than writing invalid JSON.</summary>
    Private Shared Sub WriteNumberOrNull(w As Utf8JsonWriter, value As Double?)
        If value.HasValue AndAlso Not Double.IsNaN(value.Value) AndAlso Not Double.IsInfinity(value.Value) Then
            w.WriteNumberValue(value.Value)
        Else
            w.WriteNullValue()
        End If
    End Sub
End Class
