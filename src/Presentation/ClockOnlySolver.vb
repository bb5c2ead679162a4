Option Strict On

''' <summary>
''' A solver that moves nothing: it only lets <see cref="World.Advance"/> set a rebuilt world's clock
''' to the time its checkpoint was taken (0 + t is exactly t), before the real solver is attached.
''' </summary>
Friend NotInheritable Class ClockOnlySolver
    Implements ISolver

    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return "clock"
        End Get
    End Property

    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return Nothing
        End Get
    End Property

    Public Sub Attach(world As World) Implements ISolver.Attach
    End Sub

    Public Sub Advance(duration As Double) Implements ISolver.Advance
    End Sub

    Public Function AdvanceWithin(duration As Double, deadline As Long) As Double Implements ISolver.AdvanceWithin
        Throw New NotSupportedException("the clock-only solver only sets the clock")
    End Function

    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
    End Sub
End Class
