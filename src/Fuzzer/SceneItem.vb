Option Strict On

''' <summary>One body or link of a <see cref="SceneDoc"/>: its id, its JSON object text, and (for a link) the ids it joins.</summary>
Friend NotInheritable Class SceneItem
    Friend Sub New(id As String, json As String, Optional joins As IReadOnlyList(Of String) = Nothing)
        Me.Id = id
        Me.Json = json
        Me.Joins = If(joins, Array.Empty(Of String)())
    End Sub

    Friend ReadOnly Property Id As String
    Friend ReadOnly Property Json As String
    ''' <summary>For a link: the body ids it needs ("a", and "b" when it names one).</summary>
    Friend ReadOnly Property Joins As IReadOnlyList(Of String)
End Class
