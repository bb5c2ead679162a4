Option Strict On

''' <summary>
''' A valid scene that the chosen solver cannot yet move as it should (for example a chain of links in the
''' event solver). The message is one plain sentence that says what and which solver can, for the command
''' line and the app to show as it is. The world is left as it was before the advance.
''' </summary>
Public NotInheritable Class UnsupportedSceneException
    Inherits NotSupportedException

    Public Sub New()
    End Sub

    Public Sub New(message As String)
        MyBase.New(message)
    End Sub

    Public Sub New(message As String, innerException As Exception)
        MyBase.New(message, innerException)
    End Sub
End Class
