Option Strict On

''' <summary>What a scene's error run found: the error and, optionally, a remark for the tables.</summary>
Friend Structure SceneMeasurement
    ''' <summary>Error in the scene's metric; NaN when it could not be measured.</summary>
    Public ReadOnly Property [Error] As Double

    ''' <summary>A secondary figure or warning, e.g. "rest at 2.31 s"; empty when none.</summary>
    Public ReadOnly Property Note As String

    Public Sub New([error] As Double, Optional note As String = "")
        Me.Error = [error]
        Me.Note = If(note, "")
    End Sub
End Structure
