Option Strict On

''' <summary>
''' Arrays written inline in tests. A helper rather than {…} literals because CA1861 (hoist constant
''' arrays into static fields) is about hot paths, and every test runs once.
''' </summary>
Friend Module Literals
    Public Function Values(Of T)(ParamArray items As T()) As T()
        Return items
    End Function
End Module
