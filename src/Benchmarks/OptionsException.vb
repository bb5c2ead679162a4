Option Strict On

''' <summary>Bad command-line input; the message is one line that names the option and the problem.</summary>
Public NotInheritable Class OptionsException
    Inherits Exception

    Public Sub New()
    End Sub

    Public Sub New(message As String)
        MyBase.New(message)
    End Sub

    Public Sub New(message As String, innerException As Exception)
        MyBase.New(message, innerException)
    End Sub
End Class
