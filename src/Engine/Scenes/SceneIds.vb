Option Strict On
Imports System.Globalization

Namespace Scenes
    ''' <summary>The id rule bodies and links share: a given id must be non-empty and unused; a missing one comes from the 1-based position.</summary>
    Friend Module SceneIds
        ''' <summary>
        ''' The id of item <paramref name="index"/>: the given one, or <paramref name="prefix"/> followed by its
        ''' 1-based position. <paramref name="owners"/> maps the ids so far to their items' indices;
        ''' <paramref name="placeOf"/> names an item's place in the file (bodies[3], links[0]).
        ''' </summary>
        Friend Function ReadId(f As JsonFields, index As Integer, owners As Dictionary(Of String, Integer), prefix As String,
                               placeOf As Func(Of Integer, String)) As String
            Dim other As Integer
            If f.Find("id") Is Nothing Then
                Dim id = prefix & (index + 1).ToString(CultureInfo.InvariantCulture)
                If owners.TryGetValue(id, other) Then
                    Throw New SceneFormatException(placeOf(index), "has no id, so it is named """ & id & """ by its position, but " & placeOf(other) & " already has that id")
                End If
                Return id
            End If
            Dim given = f.OptionalString("id")
            If given.Length = 0 Then Throw New SceneFormatException(f.PlaceOf("id"), "must not be empty")
            If owners.TryGetValue(given, other) Then
                Throw New SceneFormatException(f.PlaceOf("id"), """" & given & """ is already the id of " & placeOf(other))
            End If
            Return given
        End Function
    End Module
End Namespace
