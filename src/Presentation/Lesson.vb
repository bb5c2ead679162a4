Option Strict On

''' <summary>One entry of the Scenes menu: a scene file, its title and one line saying what it shows.</summary>
Public NotInheritable Class Lesson
    ''' <param name="path">the scene file</param>
    ''' <param name="title">the menu's words for it</param>
    ''' <param name="summary">what it shows, one line ("" for none)</param>
    Public Sub New(path As String, title As String, summary As String)
        If String.IsNullOrEmpty(path) Then Throw New ArgumentException("a lesson needs a scene file", NameOf(path))
        Me.Path = path
        Me.Title = If(title, "")
        Me.Summary = If(summary, "")
    End Sub

    ''' <summary>The scene file.</summary>
    Public ReadOnly Property Path As String

    ''' <summary>The scene file's name, without its folder.</summary>
    Public ReadOnly Property FileName As String
        Get
            Return IO.Path.GetFileName(Path)
        End Get
    End Property

    ''' <summary>"Newton's cradle".</summary>
    Public ReadOnly Property Title As String

    ''' <summary>One line saying what the scene shows; "" when the index gives none.</summary>
    Public ReadOnly Property Summary As String

    ''' <summary>The menu item: the title, then what it shows.</summary>
    Public ReadOnly Property MenuText As String
        Get
            Return If(Summary.Length = 0, Title, Title & " — " & Summary)
        End Get
    End Property
End Class
