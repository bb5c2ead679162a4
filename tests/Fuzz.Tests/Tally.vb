Option Strict On

''' <summary>Counts by name, for coverage reports.</summary>
Public NotInheritable Class Tally
    Private ReadOnly _counts As New SortedDictionary(Of String, Integer)(StringComparer.Ordinal)

    Public Sub Add(key As String)
        Dim n As Integer
        _counts.TryGetValue(key, n)
        _counts(key) = n + 1
    End Sub

    Public Function [Of](key As String) As Integer
        Dim n As Integer
        _counts.TryGetValue(key, n)
        Return n
    End Function

    Public ReadOnly Property Keys As IEnumerable(Of String)
        Get
            Return _counts.Keys
        End Get
    End Property
End Class
