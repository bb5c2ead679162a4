Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>How the benchmark advances a world while it looks at it.</summary>
Public Class SamplingRunTests
    ''' <summary>A solver that only writes down how long each Advance was.</summary>
    Private NotInheritable Class RecordingSolver
        Implements ISolver
        Public ReadOnly Property Durations As New List(Of Double)
        Public ReadOnly Property Name As String = "recording" Implements ISolver.Name
        Public ReadOnly Property TimeStep As Double? = 0.001 Implements ISolver.TimeStep
        Public Sub Attach(world As World) Implements ISolver.Attach
            _world = world
        End Sub
        Private _world As World
        Public Sub Advance(duration As Double) Implements ISolver.Advance
            Durations.Add(duration)
        End Sub
        Public Function AdvanceWithin(duration As Double, deadline As Long) As Double Implements ISolver.AdvanceWithin
            Durations.Add(duration)
            Return _world.Time + duration
        End Function
        Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        End Sub
    End Class

    <Fact>
    Public Sub Run_AdvancesByTheSameExactSlice_ThenTheRest_EvenLateInARun()
        Dim w As New World(1, 1, 0)
        Dim solver As New RecordingSolver()
        w.Solver = solver
        w.Advance(2.6) ' a late start, where the clock's rounding is larger than a step's
        Dim looks As New List(Of Double)
        Assert.True(Sampling.Run(w, 0.0105, 0.001, Function(t)
                                                       looks.Add(t)
                                                       Return True
                                                   End Function, New RunBudget(60)))
        Assert.Equal(11, looks.Count)
        Assert.Equal(12, solver.Durations.Count)
        Assert.All(solver.Durations.Skip(1).Take(10), Sub(d) Assert.Equal(0.001, d))
        Assert.Equal(0.0005, solver.Durations.Last(), 12)
    End Sub

    <Fact>
    Public Sub Run_StopsWhenTheLookSaysSo_OrWhenTheBudgetIsSpent()
        Dim w As New World(1, 1, 0)
        w.Solver = New RecordingSolver()
        Dim n = 0
        Assert.True(Sampling.Run(w, 1.0, 0.1, Function(t)
                                                  n += 1
                                                  Return n < 3
                                              End Function, New RunBudget(60)))
        Assert.Equal(3, n)
        Assert.False(Sampling.Run(w, 1.0, 0.1, Function(t) True, New RunBudget(0)))
    End Sub

    <Fact>
    Public Sub SliceOf_IsAWholeNumberOfSteps()
        Assert.Equal(0.1, Sampling.SliceOf(1 / 4000.0, 0.1), 15)
        Assert.Equal(1 / 30.0, Sampling.SliceOf(1 / 30.0, 0.01), 15) ' never less than one step
        Assert.Equal(3 / 30.0, Sampling.SliceOf(1 / 30.0, 0.1), 15)
    End Sub
End Class
