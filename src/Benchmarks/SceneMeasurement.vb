Option Strict On

''' <summary>What a scene's error run found: the error and, optionally, a remark for the tables.</summary>
Friend Structure SceneMeasurement
    ''' <summary>Error in the scene's metric; NaN when it could not be measured.</summary>
    Public ReadOnly Property [Error] As Double

    ''' <summary>A secondary figure or warning, e.g. "rest at 2.31 s"; empty when none.</summary>
    Public ReadOnly Property Note As String

    ''' <summary>False when the run was stopped by its wall-clock budget before the end.</summary>
    Public ReadOnly Property Completed As Boolean

    Public Sub New([error] As Double, Optional note As String = "", Optional completed As Boolean = True)
        Me.Error = [error]
        Me.Note = If(note, "")
        Me.Completed = completed
    End Sub

    ''' <summary>A run the budget stopped: no error, and a note saying how far it got.</summary>
    Public Shared Function Stopped(world As World, budget As RunBudget) As SceneMeasurement
        If budget Is Nothing Then Throw New ArgumentNullException(NameOf(budget))
        Return New SceneMeasurement(Double.NaN, budget.StoppedNote(world), completed:=False)
    End Function
End Structure
