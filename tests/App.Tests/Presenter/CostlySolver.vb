Option Strict On

''' <summary>
''' A solver whose work costs a known wall-clock time: every advance moves a test's clock on by
''' <see cref="CostPerSimulatedSecond"/> × the simulated seconds advanced, s. The motion itself is
''' the inner solver's (or none, with no inner solver: only the world's clock moves). The deadline
''' it is given is the real stopwatch's, which a test's clock never reaches: only the presenter's own
''' reading of the test's clock can stop a frame.
''' </summary>
Public NotInheritable Class CostlySolver
    Implements ISolver

    Private ReadOnly _inner As ISolver
    Private _world As World

    ''' <param name="inner">the solver that moves the bodies, or Nothing to move none</param>
    Public Sub New(inner As ISolver, costPerSimulatedSecond As Double)
        _inner = inner
        Me.CostPerSimulatedSecond = costPerSimulatedSecond
    End Sub

    ''' <summary>Wall-clock seconds of the test's clock each simulated second costs.</summary>
    Public Property CostPerSimulatedSecond As Double

    ''' <summary>The test's clock, s: what the presenter reads as its wall clock.</summary>
    Public Property Clock As Double

    ''' <summary>Advances asked for, one per call.</summary>
    Public ReadOnly Property Durations As New List(Of Double)

    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return If(_inner Is Nothing, "costly", _inner.Name)
        End Get
    End Property

    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return _inner?.TimeStep
        End Get
    End Property

    Public Sub Attach(world As World) Implements ISolver.Attach
        _world = world
        _inner?.Attach(world)
    End Sub

    Public Sub Advance(duration As Double) Implements ISolver.Advance
        AdvanceWithin(duration, Long.MaxValue)
    End Sub

    Public Function AdvanceWithin(duration As Double, deadline As Long) As Double Implements ISolver.AdvanceWithin
        Durations.Add(duration)
        Clock += duration * CostPerSimulatedSecond
        If _inner Is Nothing Then Return _world.Time + duration
        Return _inner.AdvanceWithin(duration, deadline)
    End Function

    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        _inner?.Invalidate(body)
    End Sub
End Class
