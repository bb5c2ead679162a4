Option Strict On
Imports Xunit

''' <summary>
''' The collection of tests that start the real app: they run one after another, not in parallel,
''' so that each window has the machine to itself and no two X servers race for a display.
''' </summary>
<CollectionDefinition(RealWindow.Name, DisableParallelization:=True)>
Public NotInheritable Class RealWindow
    Public Const Name As String = "Real window"
End Class
