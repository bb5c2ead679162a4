Option Strict On
Imports Xunit

''' <summary>
''' Tests that run many scenes under the wall-time cap: they run one at a time, after the other tests of
''' this assembly, so that they do not take each other's cores and trip the cap.
''' </summary>
<CollectionDefinition(FuzzRuns.Name, DisableParallelization:=True)>
Public NotInheritable Class FuzzRuns
    Public Const Name As String = "Fuzz runs"
End Class
