Option Strict On

''' <summary>
''' Bad input from the person at the keyboard (an unknown option, a missing file, an invalid scene):
''' exit status 2, and the message, one line saying what and where, goes to standard error.
''' </summary>
Public NotInheritable Class BadInputException
    Inherits Exception

    Public Sub New()
        Me.New("bad input")
    End Sub

    Public Sub New(message As String)
        MyBase.New(message)
    End Sub

    Public Sub New(message As String, innerException As Exception)
        MyBase.New(message, innerException)
    End Sub
End Class
