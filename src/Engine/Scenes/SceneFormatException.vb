Option Strict On

Namespace Scenes
    ''' <summary>
    ''' A scene file that cannot be loaded. <see cref="Exception.Message"/> is one line, "place: problem",
    ''' for example "bodies[3].radius: must be greater than 0"; <see cref="Place"/> is a JSON path with
    ''' 0-based indexes ("format", "world.width", "bodies[2].id", "bodies[5]"), or the file's path when
    ''' the file itself cannot be read.
    ''' </summary>
    Public Class SceneFormatException
        Inherits Exception

        ''' <summary>An error with no place.</summary>
        Public Sub New()
            Me.New("document", "is not a valid scene")
        End Sub

        ''' <summary>An error whose whole text is <paramref name="message"/>; it has no place.</summary>
        Public Sub New(message As String)
            MyBase.New(message)
            Place = ""
            Problem = message
        End Sub

        ''' <summary>An error whose whole text is <paramref name="message"/>, caused by <paramref name="innerException"/>.</summary>
        Public Sub New(message As String, innerException As Exception)
            MyBase.New(message, innerException)
            Place = ""
            Problem = message
        End Sub

        ''' <summary>An error at <paramref name="place"/>; the message is "place: problem".</summary>
        Public Sub New(place As String, problem As String)
            Me.New(place, problem, Nothing)
        End Sub

        ''' <summary>An error at <paramref name="place"/> caused by <paramref name="innerException"/>.</summary>
        Public Sub New(place As String, problem As String, innerException As Exception)
            MyBase.New(place & ": " & problem, innerException)
            Me.Place = place
            Me.Problem = problem
        End Sub

        ''' <summary>Where the problem is: a JSON path such as "bodies[3].radius", or the file's path.</summary>
        Public ReadOnly Property Place As String

        ''' <summary>What is wrong there, for example "must be greater than 0".</summary>
        Public ReadOnly Property Problem As String
    End Class
End Namespace
