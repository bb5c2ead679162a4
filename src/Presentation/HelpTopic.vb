Option Strict On

''' <summary>One page of a help window: a title and plain text.</summary>
Public NotInheritable Class HelpTopic
    ''' <summary>Makes a page.</summary>
    Public Sub New(title As String, text As String)
        Me.Title = title
        Me.Text = text
    End Sub

    ''' <summary>Shown in the list of pages.</summary>
    Public ReadOnly Property Title As String
    ''' <summary>The page, plain text with blank lines between paragraphs.</summary>
    Public ReadOnly Property Text As String
End Class
