Option Strict On

''' <summary>
''' A scene with a known answer: how to build it (always through <see cref="Scenarios"/>, as the tests
''' do), how long to run it, and how far a solver's result is from the closed form.
''' </summary>
Friend Interface IBenchScene
    ''' <summary>Short name used on the command line, in JSON and in file names.</summary>
    ReadOnly Property Name As String

    ''' <summary>Heading in docs/benchmarks.md.</summary>
    ReadOnly Property Title As String

    ''' <summary>One or two sentences: the set-up and the closed form the error is measured against.</summary>
    ReadOnly Property Description As String

    ''' <summary>What the error measures, with its unit.</summary>
    ReadOnly Property ErrorMetric As String

    ''' <summary>Simulated seconds per run.</summary>
    ReadOnly Property SimulatedSeconds As Double

    ''' <summary>A fresh copy of the scene, without a solver.</summary>
    Function Build() As World

    ''' <summary>
    ''' Runs <paramref name="world"/> (solver attached, time 0) for <see cref="SimulatedSeconds"/> and
    ''' measures its error. <paramref name="sampleStep"/> (s) is how often the scene may look at the
    ''' state: one step for a stepping solver (it has no state in between), finer for the event solver.
    ''' A run that outlasts <paramref name="budget"/> returns <see cref="SceneMeasurement.Stopped"/>.
    ''' </summary>
    Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement
End Interface
