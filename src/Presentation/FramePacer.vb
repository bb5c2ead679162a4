Option Strict On

''' <summary>
''' The frame budget: how long a frame may spend advancing the world, how the advance keeps to it,
''' and how much simulated time it held back (see FrameBudget).
''' </summary>
Friend NotInheritable Class FramePacer
    Private ReadOnly _stage As Stage
    Private ReadOnly _speed As Func(Of Double)
    Private ReadOnly _advance As Func(Of Double, Double, Double)

    ''' <param name="speed">simulated seconds per real second now (the Speed slider)</param>
    ''' <param name="advance">advances the world on show by up to so many simulated seconds within so many wall-clock seconds; returns the seconds done</param>
    Public Sub New(stage As Stage, speed As Func(Of Double), advance As Func(Of Double, Double, Double))
        _stage = stage
        _speed = speed
        _advance = advance
    End Sub

    ''' <summary>
    ''' The wall-clock time one piece of an advance is sized to take, s (see <see cref="AdvanceWithinBudget"/>):
    ''' the clock is read between pieces, so a frame overruns its budget by about this much at most,
    ''' unless a single instant costs more (a cascade of collisions in a pile is not cut).
    ''' </summary>
    Public Const PieceSeconds As Double = 0.0015
    ''' <summary>
    ''' The shortest piece, as a fraction of the frame's simulated time: every piece ends with every
    ''' body's state written back, so much shorter pieces would spend the frame on that.
    ''' </summary>
    Public Const MinPieceFraction As Double = 1.0 / 64
    ''' <summary>The first piece a scene is advanced by, as a fraction of the frame's simulated time (its cost is not known yet).</summary>
    Public Const FirstPieceFraction As Double = 1.0 / 8

    Private _fixedBudget As Double?
    Private Shared ReadOnly Watch As Diagnostics.Stopwatch = Diagnostics.Stopwatch.StartNew()

    ''' <summary>What is left of a 60 Hz frame for advancing the world, after the frame's measured other work.</summary>
    Public ReadOnly Property Budget As New FrameBudget()

    ''' <summary>
    ''' Wall-clock seconds, from any start: what the budget is measured with. A stopwatch unless a
    ''' test gives a clock of its own.
    ''' </summary>
    Public Property WallClock As Func(Of Double) = Function() Watch.Elapsed.TotalSeconds

    ''' <summary>
    ''' Wall-clock seconds one frame may spend advancing the world: what <see cref="Budget"/> leaves of
    ''' a 60 Hz frame, unless set here (then the value set, for good). A scene that needs more
    ''' collisions than fit shows slower time, and says so, instead of stuttering or freezing the window.
    ''' </summary>
    Public Property FrameBudgetSeconds As Double
        Get
            Return If(_fixedBudget, Budget.StepSeconds)
        End Get
        Set(value As Double)
            _fixedBudget = Math.Max(0, value)
        End Set
    End Property

    ''' <summary>Whether the last frame fell short of the chosen speed (see <see cref="FrameBudgetSeconds"/>).</summary>
    Public ReadOnly Property IsRunningSlow As Boolean

    ''' <summary>Frames that fell short of the chosen speed since the presenter started.</summary>
    Public ReadOnly Property SlowedFrames As Long

    ''' <summary>
    ''' Simulated seconds the budget held back since the presenter started: how far time on screen
    ''' is behind what the Speed slider asked for. Shown by the frame benchmark, so a budget that
    ''' hides a slow engine is seen.
    ''' </summary>
    Public ReadOnly Property HeldBackSeconds As Double

    Public Function ClockSeconds() As Double
        Return WallClock.Invoke()
    End Function

    ''' <summary>
    ''' The window spent <paramref name="seconds"/> (s) of this frame outside the presenter's Tick:
    ''' painting the canvas, refreshing the log or a graph. The next frames' budget leaves room for it.
    ''' </summary>
    Public Sub NoteFrameWork(seconds As Double)
        Budget.AddOtherWork(seconds)
    End Sub

    ''' <summary>
    ''' Advances by up to <paramref name="seconds"/> within the frame's budget; returns the simulated
    ''' seconds done. The event solver ends an advance exactly where asked and carries on from the same
    ''' predictions, so a frame may be advanced in pieces with the same result as in one, and the clock
    ''' is read between them. Each piece is sized from the wall-clock cost per simulated second of the
    ''' last one to take about <see cref="PieceSeconds"/>, so a quiet frame is one piece and a burst of
    ''' piling many short ones; a piece is not begun when its expected cost would not fit in what is
    ''' left. A stepping solver (or the event solver with links, or with a body being carried: its
    ''' carry aims at the frame's end) gets one advance with the budget as its deadline, which it
    ''' checks itself.
    ''' </summary>
    Public Function AdvanceWithinBudget(seconds As Double) As Double
        Dim budget = FrameBudgetSeconds
        Dim start = ClockSeconds()
        Dim t0 = _stage.World.Time
        If _stage.World.Solver.TimeStep.HasValue OrElse _stage.World.Links.Count > 0 OrElse _stage.World.DraggedBody IsNot Nothing Then
            Return _advance(seconds, budget)
        End If
        Dim target = t0 + seconds
        Dim shortest = seconds * MinPieceFraction
        Do While _stage.World.Time < target
            Dim spent = ClockSeconds() - start
            Dim left = target - _stage.World.Time
            ' Before any piece has been timed, an eighth of the frame finds out what the scene costs.
            Dim piece = If(_costRate > 0, Math.Max(shortest, PieceSeconds / _costRate), seconds * FirstPieceFraction)
            ' The first piece always runs: every frame moves the world.
            If _stage.World.Time > t0 AndAlso spent + Math.Min(piece, left) * _costRate > budget Then Exit Do
            Dim before = _stage.World.Time
            Dim duration = If(piece >= left, ExactClock.DurationTo(_stage.World.Time, target), piece)
            _advance(duration, Math.Max(0, budget - spent))
            Dim cost = ClockSeconds() - start - spent
            If _stage.World.Time > before Then _costRate = cost / (_stage.World.Time - before)
            ' Short of the piece's end: the solver's own deadline passed (stop), or a checkpoint of a
            ' replayed run lay inside the piece (go on from it).
            If _stage.World.Time <= before OrElse cost + spent >= budget Then Exit Do
        Loop
        Return _stage.World.Time - t0
    End Function

    ''' <summary>Wall-clock seconds per simulated second of the last piece advanced (0 before the first).</summary>
    Private _costRate As Double

    ''' <summary>
    ''' Counts a frame that fell short of the simulated time asked, and says so once time on screen has
    ''' fallen <see cref="SlowNoticeSeconds"/> behind in one stretch of slow frames (once per stretch:
    ''' a burst of slow frames does not repeat the message).
    ''' </summary>
    Public Sub NoteAdvance(asked As Double, done As Double)
        Dim slow = done < asked * (1 - 1.0E-9)
        If slow Then
            _SlowedFrames += 1
            _HeldBackSeconds += asked - done
            _streakBehind += (asked - done) / _speed()
            _keptUpSeconds = 0
        Else
            _streakBehind = 0
            _streakNoticed = False
            _keptUpSeconds += asked / _speed()
        End If
        If slow AndAlso Not _IsRunningSlow Then _stage.Emit("running slow")
        _IsRunningSlow = slow
        If slow AndAlso Not _streakNoticed AndAlso _streakBehind >= SlowNoticeSeconds Then
            _streakNoticed = True
            ' True until the scene has kept up for a while (the balls of a peg board all at rest).
            If _stage.Message <> SlowMessage Then _stage.ShowMessage(SlowMessage, Function() _keptUpSeconds < KeptUpSeconds)
        End If
    End Sub

    ''' <summary>
    ''' How far behind the wall clock time on screen may fall in one stretch of slow frames before the
    ''' message says so, s: a single slow frame (code compiled on its first use, another program busy
    ''' for a moment) is not worth a message; a tenth of a second behind is about what an eye notices.
    ''' </summary>
    Public Const SlowNoticeSeconds As Double = 0.1

    ''' <summary>Real seconds time on screen has fallen behind in the current stretch of slow frames.</summary>
    Private _streakBehind As Double
    ''' <summary>Real seconds the scene has kept up with the Speed slider since its last slow frame.</summary>
    Private _keptUpSeconds As Double

    ''' <summary>How long a scene must keep up before the message that it cannot goes, s: long enough not to flicker on and off.</summary>
    Public Const KeptUpSeconds As Double = 1.0

    ''' <summary>Whether the current stretch of slow frames has been told.</summary>
    Private _streakNoticed As Boolean

    ''' <summary>The message while a scene cannot keep up with the Speed slider.</summary>
    Public Const SlowMessage As String = "This scene needs more collisions than the computer can work out in real time: time on screen runs slower than the Speed slider says."
End Class
