Option Strict On
Imports System.Globalization

''' <summary>
''' A pile of boxes of mixed sizes dropped into a container (e = 0.3): how long it takes to settle, that
''' nothing overlaps at the end, and that the energy books balance. The same scene runs in Box2D 2.4.1
''' (src/Benchmarks/box2d/box_pile.cpp) for comparison.
''' </summary>
Friend NotInheritable Class BoxPileScene
    Implements IBenchScene, ISettlingScene

    ''' <summary>The 200 boxes in a container 10 m wide: a layer or two deep.</summary>
    Public Const WideName As String = "box-pile"
    ''' <summary>The 200 boxes in a container 3 m wide: stacked 10 and more deep.</summary>
    Public Const DeepName As String = "box-pile-deep"

    Private Const Restitution As Double = 0.3
    ''' <summary>
    ''' A stepping solver's pile is at rest once every box moves slower than this (m/s) for
    ''' <see cref="StillFor"/>: Box2D's own sleep test (b2_linearSleepTolerance, b2_timeToSleep).
    ''' </summary>
    Public Const StillSpeed As Double = 0.01
    ''' <summary>s; see <see cref="StillSpeed"/>.</summary>
    Public Const StillFor As Double = 0.5
    ''' <summary>How long (s) the error run goes on after the pile came to rest, to see that it stays so.</summary>
    Private Const KeptFor As Double = 1.0
    ''' <summary>How often the pile is looked at, s (rounded to whole time steps).</summary>
    Private Const LookEvery As Double = 1 / 60.0

    Private ReadOnly _count As Integer
    Private ReadOnly _width As Double

    ''' <param name="name">scene name on the command line</param>
    ''' <param name="count">boxes</param>
    ''' <param name="width">container width, m</param>
    ''' <param name="seconds">simulated seconds of a run (a pile that has not settled by then is reported so)</param>
    Public Sub New(name As String, count As Integer, width As Double, seconds As Double)
        Me.Name = name
        _count = count
        _width = width
        SimulatedSeconds = seconds
        Dim n = count.ToString(CultureInfo.InvariantCulture)
        Dim w = width.ToString("0.#", CultureInfo.InvariantCulture)
        Title = "Box pile: " & n & " boxes of mixed sizes into a container " & w & " m wide, e = 0.3"
        Description =
            "Scenarios.BoxPile(" & n & " boxes, " & w & " m wide, e = 0.3): frictionless boxes that never rotate, sides 0.2–0.5 m, 10 kg/m², " &
            "wait in rows and fall into the container together; the pile settles. There is no closed form for the heap. Error = the deepest " &
            "overlap at the end (box–box or box–wall, m; the error run ends 1 s after the pile came to rest, or at the end). The note says when every box was at rest (the event solver: every box asleep or " &
            "standing still; a stepping solver: every box slower than 1 cm/s for 0.5 s, Box2D's own sleep test) and how far kinetic + " &
            "potential energy + the energy the collisions took (World.Dissipated) ended from the starting energy. The second table times " &
            "each run until the pile is at rest, beside Box2D 2.4.1 on the same scene at 60 Hz (boxes with fixed rotation, friction 0, " &
            "restitution 0.3, 8 velocity and 3 position iterations, run until every body sleeps; its boxes' rounded skin of " &
            "b2_polygonRadius is inside the box, so both engines collide the same outlines): " &
            "src/Benchmarks/box2d/box_pile.cpp, built by scripts/box2d-reference.sh."
    End Sub

    Public ReadOnly Property Name As String Implements IBenchScene.Name
    Public ReadOnly Property Title As String Implements IBenchScene.Title
    Public ReadOnly Property Description As String Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max overlap at the end (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double Implements IBenchScene.SimulatedSeconds

    ''' <summary>Boxes in the pile.</summary>
    Public ReadOnly Property Count As Integer
        Get
            Return _count
        End Get
    End Property

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.BoxPile(_count, _width, Restitution)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim startEnergy = world.KineticEnergy() + world.PotentialEnergy()
        Dim watch As New RestWatch(world)
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, LookEvery),
                                    Function(t)
                                        ' At rest and still so a second later: it stays so (the run's one
                                        ' purpose past rest is to see that), and the rest adds nothing.
                                        Return Not (watch.Look(t) AndAlso t - watch.RestSince >= KeptFor - 1.0E-9)
                                    End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Dim drift = world.KineticEnergy() + world.PotentialEnergy() + world.Dissipated - startEnergy
        Dim note = If(Double.IsNaN(watch.RestSince),
                      "not at rest after " & SimulatedSeconds.ToString("0.#", CultureInfo.InvariantCulture) & " s (" &
                      watch.Moving.ToString(CultureInfo.InvariantCulture) & " of " & _count.ToString(CultureInfo.InvariantCulture) & " boxes moving)",
                      "all " & _count.ToString(CultureInfo.InvariantCulture) & " at rest from " & watch.RestSince.ToString("0.000", CultureInfo.InvariantCulture) & " s") &
                   "; KE + PE + dissipated − E0 = " & NumberText.Sci(drift) & " J (" & NumberText.Sci(Math.Abs(drift) / startEnergy) & " of E0)"
        Dim floating = Unsupported(world, SupportGap)
        If floating > 0 Then note &= "; " & floating.ToString(CultureInfo.InvariantCulture) & " boxes with nothing under them (within " & NumberText.Sci(SupportGap) & " m)"
        Return New SceneMeasurement(Overlap.DeepestBetweenBoxes(world), note)
    End Function

    ''' <summary>How far (m) a resting box's bottom may be from what holds it up and still count as held.</summary>
    Public Const SupportGap As Double = 0.000000001

    ''' <summary>
    ''' Movable boxes whose bottom is neither on the floor nor on the top of a box under it (with some
    ''' width in common, or corner on corner: a box that cannot turn is held even there), within
    ''' <paramref name="gap"/> m. With no friction and no rotation nothing but a support under a box can
    ''' hold it against gravity, so a pile at rest has none.
    ''' </summary>
    Public Shared Function Unsupported(world As World, gap As Double) As Integer
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim boxes = world.Rectangles
        Dim count = 0
        For Each a In boxes
            If a.IsFixed OrElse Math.Abs(a.Min.Y) <= gap Then Continue For
            Dim held = boxes.Any(Function(b) b IsNot a AndAlso Math.Abs(b.Max.Y - a.Min.Y) <= gap AndAlso
                                             Math.Min(a.Max.X, b.Max.X) - Math.Max(a.Min.X, b.Min.X) >= 0)
            If Not held Then count += 1
        Next
        Return count
    End Function

    Public Function RunToRest(world As World, budget As RunBudget) As Double Implements ISettlingScene.RunToRest
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If world.Solver Is Nothing Then Throw New ArgumentException("the world needs a solver", NameOf(world))
        Dim watch As New RestWatch(world)
        Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(If(world.Solver.TimeStep, SceneRunner.EventSampleStep), LookEvery),
                     Function(t) Not watch.Look(t), budget)
        Return watch.RestSince
    End Function

    ''' <summary>
    ''' Whether every box of a world is at rest, looked at now and then. With the event solver a box is at
    ''' rest when it is asleep or stands still (speed exactly 0); with a stepping solver, when every box has
    ''' moved slower than <see cref="StillSpeed"/> for <see cref="StillFor"/> (a stepping solver's pile
    ''' never stands exactly still).
    ''' </summary>
    Friend NotInheritable Class RestWatch
        Private ReadOnly _world As World
        Private ReadOnly _event As EventDrivenSolver
        Private _slowSince As Double = Double.NaN

        Public Sub New(world As World)
            _world = world
            _event = TryCast(world.Solver, EventDrivenSolver)
        End Sub

        ''' <summary>When the pile was found at rest (s) and has stayed so since; NaN while it is not.</summary>
        Public ReadOnly Property RestSince As Double = Double.NaN

        ''' <summary>Boxes not at rest at the last look.</summary>
        Public ReadOnly Property Moving As Integer

        ''' <summary>Looks at the pile at time <paramref name="t"/> (s); True when it is at rest.</summary>
        Public Function Look(t As Double) As Boolean
            Dim moving = 0
            For Each b In _world.Movables
                If _event IsNot Nothing Then
                    If Not _event.IsAsleep(b) AndAlso b.Velocity.Length > 0 Then moving += 1
                ElseIf b.Velocity.Length >= StillSpeed Then
                    moving += 1
                End If
            Next
            _Moving = moving
            If moving > 0 Then
                _slowSince = Double.NaN
                _RestSince = Double.NaN
                Return False
            End If
            If _event IsNot Nothing Then
                If Double.IsNaN(_RestSince) Then _RestSince = t
                Return True
            End If
            If Double.IsNaN(_slowSince) Then _slowSince = t
            If t - _slowSince >= StillFor - 1.0E-9 Then
                If Double.IsNaN(_RestSince) Then _RestSince = t
                Return True
            End If
            Return False
        End Function
    End Class
End Class
