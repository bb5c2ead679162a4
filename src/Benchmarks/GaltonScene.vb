Option Strict On
Imports System.Globalization

''' <summary>A Galton board of 500 balls: how fast it runs, and that no ball ends inside another body.</summary>
Friend NotInheritable Class GaltonScene
    Implements IBenchScene, IRealTimeScene

    Private Const Balls As Integer = 500

    Public ReadOnly Property Name As String = "galton" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Galton board: 500 balls through 234 pegs" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.GaltonBoard(500 balls, 12 rows of pegs, 20 bins, 10 shelves; e = 0.5): balls slide off sloping shelves, fall " &
        "through a funnel and a chute onto 234 fixed pegs and pile up in the bins, for 15 s. There is no closed form for where each " &
        "ball ends; error = the deepest overlap at the end (between balls, or a ball and a peg, bin, shelf, wall or the container, m), " &
        "and the note gives how many balls reached the bins, how many of those standing still are not held there (their " &
        "frictionless contact forces and weight do not balance), and how many times faster than real time the timed runs went (their median)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max overlap at the end (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 15.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.GaltonBoard(Balls, 12, 20, 10)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If Not Sampling.Advance(world, SimulatedSeconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Dim binTop = world.Rectangles.Where(Function(r) r.Id.StartsWith("bin", StringComparison.Ordinal)).Max(Function(r) r.Max.Y)
        Dim inBins = world.Circles.Where(Function(c) Not c.IsFixed AndAlso c.Position.Y < binTop).Count()
        Return New SceneMeasurement(Overlap.Deepest(world),
                                    inBins.ToString(CultureInfo.InvariantCulture) & " of " & Balls.ToString(CultureInfo.InvariantCulture) & " balls in the bins" &
                                    RestBalance.Note(world))
    End Function
End Class
