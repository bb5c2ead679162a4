Option Strict On

''' <summary>
''' The size of the quick pass that runs with every test run (and so in CI): how many generated scenes,
''' from which seed, and the wall-time cap of one run. FUZZ_QUICK_SCENES and FUZZ_QUICK_SEED override
''' the first two, for a longer pass or another stretch of seeds without a rebuild.
''' </summary>
Public NotInheritable Class QuickPass
    Private Sub New()
    End Sub

    ''' <summary>Scenes in the quick pass: each runs with every solver (the event solver twice).</summary>
    Public Shared ReadOnly Property Scenes As Integer = FromEnvironment("FUZZ_QUICK_SCENES", 400)

    ''' <summary>The first scene's seed; the others follow it.</summary>
    Public Shared ReadOnly Property FirstSeed As Integer = FromEnvironment("FUZZ_QUICK_SEED", 1)

    ''' <summary>Simulated time of a run, s (fast scenes run shorter: see Campaign.PlanFor).</summary>
    Public Const Time As Double = 1.0

    ''' <summary>Bodies in a scene, at most about (obstacles come on top).</summary>
    Public Const MaxBodies As Integer = 40

    ''' <summary>
    ''' Wall-clock seconds one run may take. The scenes are small (at most about 40 bodies, 1 s): most run in
    ''' well under a second, and a run this much slower than that is a runaway, not a slow machine.
    ''' </summary>
    Public Const Cap As Double = 20.0

    ''' <summary>
    ''' Failures the quick pass knows of: open defects of the event solver, by seed and invariant. They are
    ''' printed with every run but do not fail it, so that any other failure (a new one) still does. An
    ''' entry goes when its defect is fixed.
    ''' </summary>
    Public Shared ReadOnly Property KnownFailures As IReadOnlyList(Of (Seed As Integer, Invariant As String)) =
        Array.Empty(Of (Seed As Integer, Invariant As String))()

    ''' <summary>
    ''' Scenes in the quick pass with every kind of body and link (segments, polygons, boxes, springs, rods and
    ''' strings, friction in half of them), run with the event solver (twice, for the sampling check).
    ''' FUZZ_QUICK_ALL_KINDS_SCENES overrides it.
    ''' </summary>
    Public Shared ReadOnly Property AllKindsScenes As Integer = FromEnvironment("FUZZ_QUICK_ALL_KINDS_SCENES", 30)

    ''' <summary>Bodies in a scene of the pass with every kind, at most about.</summary>
    Public Const AllKindsMaxBodies As Integer = 30

    ''' <summary>The share of the scenes with every kind that have friction (the "rough" fraction).</summary>
    Public Const AllKindsRough As Double = 0.5

    ''' <summary>
    ''' Failures the pass with every kind knows of, by seed and invariant, printed but not failing it. Seeds 14 and
    ''' 15 are groups integrated under very stiff springs (a 40 µg ball pulled at 10⁵ m/s², a 0.1 mg ball on a
    ''' spring compressed by 2.8 m): the integrator's error control needs steps of microseconds, so on a loaded
    ''' machine the run may not reach 1 s within the cap.
    ''' </summary>
    Public Shared ReadOnly Property AllKindsKnownFailures As IReadOnlyList(Of (Seed As Integer, Invariant As String)) =
        {(14, "wall-time"), (15, "wall-time")}

    Private Shared Function FromEnvironment(name As String, fallback As Integer) As Integer
        Dim text = Environment.GetEnvironmentVariable(name)
        Dim value As Integer
        If text IsNot Nothing AndAlso Integer.TryParse(text, Globalization.NumberStyles.Integer, Globalization.CultureInfo.InvariantCulture, value) AndAlso value > 0 Then Return value
        Return fallback
    End Function
End Class
