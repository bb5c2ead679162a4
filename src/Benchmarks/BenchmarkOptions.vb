Option Strict On
Imports System.Globalization

''' <summary>
''' The command line. Public options choose the mode and the outputs; the hidden --child-* options
''' are how the benchmark runs one case in a child process of itself.
''' </summary>
Friend NotInheritable Class BenchmarkOptions
    ''' <summary>Every scene, in report order.</summary>
    Public Shared ReadOnly Property AllScenes As IReadOnlyList(Of String) =
        {"bouncing-apex", "bouncing-rest", "projectile", "oblique-hit", "cradle", "gas-energy", "pile", "ramp-slide", "box-drop", BoxPileScene.WideName, BoxPileScene.DeepName, "pendulum", "spring", "rope", "cradle-strings", "drag-projectile", "tanh-fall", "floating-box", "galton", "mixed"}

    ''' <summary>The solvers compared, as SolverFactory names them.</summary>
    Public Shared ReadOnly Property AllSolvers As IReadOnlyList(Of String) = {"event", "euler", "verlet"}

    ''' <summary>Time steps of the full run, s: 1/30 to 1/4000.</summary>
    Public Shared ReadOnly Property FullTimeSteps As IReadOnlyList(Of Double) =
        {1 / 30.0, 1 / 60.0, 1 / 120.0, 1 / 250.0, 1 / 500.0, 1 / 1000.0, 1 / 2000.0, 1 / 4000.0}

    ''' <summary>Time steps of the quick run, s.</summary>
    Public Shared ReadOnly Property QuickTimeSteps As IReadOnlyList(Of Double) = {1 / 30.0, 1 / 250.0, 1 / 1000.0, 1 / 4000.0}

    Public Const Usage As String =
        "usage: Benchmarks [--quick] [--json FILE] [--out DIR] [--no-frame]" & vbLf &
        "                  [--scenes a,b,...] [--solvers event,euler,verlet] [--dts 1/60,1/1000,...]" & vbLf &
        "                  [--gas-sizes 100,1000,...] [--gas-rounds K] [--repeats K] [--app PATH]" & vbLf &
        "  --quick      a short run for CI (under a minute); without it every scene, dt and N (about 10 minutes)" & vbLf &
        "  --json FILE  also write every result as JSON, for comparing runs" & vbLf &
        "  --out DIR    where docs/benchmarks.md and the SVG plots go (default: docs)" & vbLf &
        "  --readme FILE  copy the report's headline figures into FILE (README.md) between its markers" & vbLf &
        "  --readme-only  with --readme: copy the figures of the report already in --out, and run nothing" & vbLf &
        "  --no-frame   skip the app's frame benchmarks (mono + Xvfb): the gas and the lesson scenes" & vbLf &
        "  --baseline-dll PATH  the Benchmarks.dll of the baseline commit: the full run times its gas beside this one's" & vbLf &
        "  --baseline-commit HASH  which commit that is, for the report" & vbLf &
        "  --baseline-note TEXT    why there is no baseline build (the report says so instead)" & vbLf &
        "  --box2d PATH  the Box2D reference program (scripts/box2d-reference.sh builds it): the box piles run in it too" & vbLf &
        "  --box2d-note TEXT  why there is no Box2D reference program (the report says so instead)" & vbLf &
        "  --baseline-rounds K     pairs of runs (baseline, then this engine, or the other way round) per size (default 7)" & vbLf &
        "  --gas-rounds K  run every gas size K times, in rounds that take the sizes in turn and every solver" & vbLf &
        "               at a size one after the other; report the median run with the range (default 3; 1 with --quick)" & vbLf &
        "  scenes: bouncing-apex, bouncing-rest, projectile, oblique-hit, cradle, gas-energy, pile, ramp-slide, box-drop, box-pile," & vbLf &
        "          box-pile-deep, pendulum," & vbLf &
        "          spring, rope, cradle-strings, drag-projectile, tanh-fall, floating-box, galton, mixed, and gas-scaling" & vbLf &
        "  gas-scaling also times the textbook baseline (a plain event-driven gas, not the engine) beside event"

    Public Property Quick As Boolean
    Public Property Help As Boolean
    Public Property JsonPath As String
    Public Property OutDir As String = "docs"

    ''' <summary>README.md to copy the headline figures into (a full run writing the committed report), or Nothing.</summary>
    Public Property ReadmePath As String

    ''' <summary>Only copy the figures of the report already in <see cref="OutDir"/> into <see cref="ReadmePath"/>; run nothing.</summary>
    Public Property ReadmeOnly As Boolean
    Public Property NoFrame As Boolean
    ''' <summary>The baseline commit's Benchmarks.dll (scripts/bench.sh builds it), or Nothing: see <see cref="BaselineComparison"/>.</summary>
    Public Property BaselineDll As String
    ''' <summary>The baseline commit's hash, for the report.</summary>
    Public Property BaselineCommit As String = ""
    ''' <summary>Why there is no baseline build, for the report; "" when there is one or none was tried.</summary>
    Public Property BaselineNote As String = ""
    ''' <summary>The Box2D reference program (scripts/box2d-reference.sh builds it), or Nothing: see <see cref="Box2dReference"/>.</summary>
    Public Property Box2dProgram As String
    ''' <summary>Why there is no Box2D reference program, for the report; "" when there is one or none was tried.</summary>
    Public Property Box2dNote As String = ""
    Public Property AppPath As String = "src/SimulatorApp/bin/Release/net48/SimulatorApp.exe"
    Public Property Scenes As IReadOnlyList(Of String) = AllScenes.Concat({GasScaling.SceneName}).ToList()
    Public Property Solvers As IReadOnlyList(Of String) = AllSolvers
    Private _timeSteps As IReadOnlyList(Of Double)
    Private _gasSizes As IReadOnlyList(Of Integer)
    Private _gasRounds As Integer
    Private _baselineRounds As Integer
    Private _repeats As Integer

    ''' <summary>Hidden: run this one scene in this process and print its results (child mode).</summary>
    Public Property ChildScene As String
    ''' <summary>Hidden: run the gas at this N in this process and print the result (child mode).</summary>
    Public Property ChildGas As Integer
    ''' <summary>Hidden: the solver of a child run.</summary>
    Public Property ChildSolver As String

    ''' <summary>The stepping solvers' time steps, s.</summary>
    Public ReadOnly Property TimeSteps As IReadOnlyList(Of Double)
        Get
            Return If(_timeSteps, If(Quick, QuickTimeSteps, FullTimeSteps))
        End Get
    End Property

    ''' <summary>The gas sizes of the scaling run.</summary>
    Public ReadOnly Property GasSizes As IReadOnlyList(Of Integer)
        Get
            Return If(_gasSizes, If(Quick, New Integer() {100, 1000}, New Integer() {100, 1000, 10000, 100000}))
        End Get
    End Property

    ''' <summary>
    ''' How many times each gas size runs. Each round runs every size once, so the rounds are minutes
    ''' apart and a shared machine's slow and quick spells (which last seconds to minutes) fall on every
    ''' size alike; the report gives the median round and the range.
    ''' </summary>
    Public ReadOnly Property GasRounds As Integer
        Get
            Return If(_gasRounds > 0, _gasRounds, If(Quick, 1, 3))
        End Get
    End Property

    ''' <summary>
    ''' How many pairs of runs compare the baseline commit's gas with this one's at each size. A run's
    ''' speed also depends on where its arrays happen to lie in memory, which differs from process to
    ''' process by a few per cent, so the comparison takes more pairs than the scaling takes rounds.
    ''' </summary>
    Public ReadOnly Property BaselineRounds As Integer
        Get
            Return If(_baselineRounds > 0, _baselineRounds, 7)
        End Get
    End Property

    ''' <summary>Timed runs per case (after one warm-up).</summary>
    Public ReadOnly Property Repeats As Integer
        Get
            Return If(_repeats > 0, _repeats, If(Quick, 3, 5))
        End Get
    End Property

    ''' <summary>Wall-clock budget of one case, s.</summary>
    Public ReadOnly Property CaseBudgetSeconds As Double
        Get
            Return If(Quick, 8.0, 30.0)
        End Get
    End Property

    ''' <summary>
    ''' How long a child that runs <paramref name="cases"/> cases may take before it is stopped: each
    ''' case keeps to its budget between slices, so this only catches a solver stuck inside one call.
    ''' </summary>
    Public Function ChildTimeout(cases As Integer) As TimeSpan
        Return TimeSpan.FromSeconds(cases * CaseBudgetSeconds * 1.25 + 30)
    End Function

    ''' <summary>How long one gas-scaling child may take before it is stopped.</summary>
    Public ReadOnly Property GasChildTimeout As TimeSpan
        Get
            Return TimeSpan.FromSeconds(If(Quick, 40, 240))
        End Get
    End Property

    ''' <summary>Simulated seconds of the gas-energy scene.</summary>
    Public ReadOnly Property GasSeconds As Double
        Get
            Return If(Quick, 2.0, 4.0)
        End Get
    End Property

    ''' <summary>
    ''' Wall-clock seconds of short advances before a scaling gas is timed, so that .NET has finished
    ''' optimising the hot code (see GasScaling.Measure).
    ''' </summary>
    Public ReadOnly Property GasWarmUpSeconds As Double
        Get
            Return If(Quick, 0.5, 3.0)
        End Get
    End Property

    ''' <summary>Wall-clock seconds one timed slice of the scaling gas should take.</summary>
    Public ReadOnly Property GasSliceSeconds As Double
        Get
            Return If(Quick, 0.15, 0.5)
        End Get
    End Property

    ''' <summary>
    ''' Longest predicted wall-clock time of one step, s, for which a stepping solver is given the next
    ''' gas size. The prediction assumes the worst (cost growing as N²), so a solver whose contact
    ''' search tests every pair is stopped before a step takes minutes, and one with a broad phase is not.
    ''' </summary>
    Public ReadOnly Property StepBudgetSeconds As Double
        Get
            Return If(Quick, 1.0, 5.0)
        End Get
    End Property

    ''' <summary>Reads the command line; throws <see cref="OptionsException"/> with a one-line message on bad input.</summary>
    Public Shared Function Parse(args As IReadOnlyList(Of String)) As BenchmarkOptions
        If args Is Nothing Then Throw New ArgumentNullException(NameOf(args))
        Dim o As New BenchmarkOptions
        Dim i = 0
        Dim value = Function(name As String) As String
                        If i + 1 >= args.Count OrElse args(i + 1).StartsWith("--", StringComparison.Ordinal) Then
                            Throw New OptionsException(name & ": needs a value")
                        End If
                        i += 1
                        Return args(i)
                    End Function
        Do While i < args.Count
            Dim a = args(i)
            Select Case a
                Case "--quick" : o.Quick = True
                Case "--help", "-h" : o.Help = True
                Case "--no-frame" : o.NoFrame = True
                Case "--json" : o.JsonPath = value(a)
                Case "--out" : o.OutDir = value(a)
                Case "--readme" : o.ReadmePath = value(a)
                Case "--readme-only" : o.ReadmeOnly = True
                Case "--app" : o.AppPath = value(a)
                Case "--baseline-dll" : o.BaselineDll = value(a)
                Case "--baseline-commit" : o.BaselineCommit = value(a)
                Case "--baseline-note" : o.BaselineNote = value(a)
                Case "--box2d" : o.Box2dProgram = value(a)
                Case "--box2d-note" : o.Box2dNote = value(a)
                Case "--scenes" : o.Scenes = ParseNames(a, value(a), AllScenes.Concat({GasScaling.SceneName}).ToList())
                Case "--solvers" : o.Solvers = ParseList(a, value(a))
                Case "--dts" : o._timeSteps = ParseList(a, value(a)).Select(Function(t) ParseTimeStep(a, t)).ToList()
                Case "--gas-sizes" : o._gasSizes = ParseList(a, value(a)).Select(Function(t) ParsePositive(a, t)).ToList()
                Case "--gas-rounds" : o._gasRounds = ParsePositive(a, value(a))
                Case "--baseline-rounds" : o._baselineRounds = ParsePositive(a, value(a))
                Case "--repeats" : o._repeats = ParsePositive(a, value(a))
                Case "--child-scene" : o.ChildScene = ParseNames(a, value(a), AllScenes)(0)
                Case "--child-gas" : o.ChildGas = ParsePositive(a, value(a))
                Case "--child-solver" : o.ChildSolver = value(a)
                Case Else
                    Throw New OptionsException("unknown option '" & a & "' (see --help)")
            End Select
            i += 1
        Loop
        Return o
    End Function

    ''' <summary>The arguments that make a child run with the same settings as this run.</summary>
    Public Function ChildArguments() As List(Of String)
        Dim list As New List(Of String)
        If Quick Then list.Add("--quick")
        list.Add("--dts")
        list.Add(String.Join(",", TimeSteps.Select(Function(t) t.ToString("R", CultureInfo.InvariantCulture))))
        list.Add("--repeats")
        list.Add(Repeats.ToString(CultureInfo.InvariantCulture))
        Return list
    End Function

    Private Shared Function ParseList(name As String, text As String) As List(Of String)
        Dim items = text.Split(","c).Select(Function(s) s.Trim()).Where(Function(s) s.Length > 0).ToList()
        If items.Count = 0 Then Throw New OptionsException(name & ": needs at least one value")
        Return items
    End Function

    Private Shared Function ParseNames(name As String, text As String, known As IReadOnlyList(Of String)) As List(Of String)
        Dim items = ParseList(name, text)
        For Each s In items
            If Not known.Contains(s) Then Throw New OptionsException(name & ": unknown scene '" & s & "' (expected one of: " & String.Join(", ", known) & ")")
        Next
        Return items
    End Function

    Private Shared Function ParseTimeStep(name As String, text As String) As Double
        Dim seconds As Double
        If Not TimeStepText.TryParse(text, seconds) Then Throw New OptionsException(name & ": '" & text & "' is not a time step greater than 0 (write 1/60 or 0.001)")
        Return seconds
    End Function

    Private Shared Function ParsePositive(name As String, text As String) As Integer
        Dim n As Integer
        If Not Integer.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, n) OrElse n < 1 Then
            Throw New OptionsException(name & ": '" & text & "' is not a whole number greater than 0")
        End If
        Return n
    End Function
End Class
