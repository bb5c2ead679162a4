Option Strict On
Imports System.Globalization
Imports System.Text
Imports System.Text.Json

''' <summary>
''' A physics-scene/1 document in pieces: the world object and one JSON object per body and per link,
''' each kept as text. Shrinking keeps a subset of the bodies (and the links whose bodies are all kept);
''' <see cref="ToText"/> writes the document every run loads, one body per line.
''' </summary>
Friend NotInheritable Class SceneDoc
    Private Const WorldField As String = "world"
    Private Const BodiesField As String = "bodies"
    Private Const LinksField As String = "links"
    Private Const Lf As Char = ChrW(10)

    Friend Sub New(worldJson As String, bodyItems As IReadOnlyList(Of SceneItem), linkItems As IReadOnlyList(Of SceneItem))
        World = worldJson
        Bodies = bodyItems
        Links = linkItems
    End Sub

    ''' <summary>The "world" object's text.</summary>
    Friend ReadOnly Property World As String
    Friend ReadOnly Property Bodies As IReadOnlyList(Of SceneItem)
    Friend ReadOnly Property Links As IReadOnlyList(Of SceneItem)

    ''' <summary>The same scene with only <paramref name="keep"/> of its bodies (in their order), and the links between kept bodies.</summary>
    Friend Function WithBodies(keep As IEnumerable(Of SceneItem)) As SceneDoc
        Dim kept = keep.ToList()
        Dim ids = New HashSet(Of String)(kept.Select(Function(b) b.Id), StringComparer.Ordinal)
        Return New SceneDoc(World, kept, Links.Where(Function(l) l.Joins.All(Function(id) ids.Contains(id))).ToList())
    End Function

    ''' <summary>The document's text: format, world, then one body (and one link) per line.</summary>
    Friend Function ToText() As String
        Dim b As New StringBuilder()
        b.Append("{"c).Append(Lf)
        b.Append("  ""format"": ""physics-scene/1"",").Append(Lf)
        b.Append("  """ & WorldField & """: ").Append(World).Append(","c).Append(Lf)
        AppendArray(b, BodiesField, Bodies, Links.Count = 0)
        If Links.Count > 0 Then AppendArray(b, LinksField, Links, True)
        b.Append("}"c).Append(Lf)
        Return b.ToString()
    End Function

    Private Shared Sub AppendArray(b As StringBuilder, name As String, items As IReadOnlyList(Of SceneItem), last As Boolean)
        b.Append("  """).Append(name).Append(""": [")
        For i = 0 To items.Count - 1
            b.Append(Lf).Append("    ").Append(items(i).Json)
            If i < items.Count - 1 Then b.Append(","c)
        Next
        If items.Count > 0 Then b.Append(Lf).Append("  ")
        b.Append("]"c)
        If Not last Then b.Append(","c)
        b.Append(Lf)
    End Sub

    ''' <summary>
    ''' Splits a scene's text into pieces, keeping each body's and link's text as written (so every number
    ''' reads back the same). A body or link without an id is given the one the format gives it (its
    ''' 1-based place; "linkN" for links), written out, so that removing others never renames it.
    ''' Throws <see cref="JsonException"/> or <see cref="FormatException"/> when the text is not a scene.
    ''' </summary>
    Friend Shared Function Parse(text As String) As SceneDoc
        Using doc = JsonDocument.Parse(text)
            Dim root = doc.RootElement
            Dim worldElement As JsonElement
            Dim bodiesElement As JsonElement
            If Not root.TryGetProperty(WorldField, worldElement) OrElse Not root.TryGetProperty(BodiesField, bodiesElement) Then
                Throw New FormatException("a scene needs ""world"" and ""bodies""")
            End If
            Dim bodyList As New List(Of SceneItem)
            Dim index = 0
            For Each e In bodiesElement.EnumerateArray()
                index += 1
                bodyList.Add(Identified(e, index.ToString(CultureInfo.InvariantCulture), Nothing))
            Next
            Dim linkList As New List(Of SceneItem)
            Dim linksElement As JsonElement
            If root.TryGetProperty(LinksField, linksElement) Then
                index = 0
                For Each e In linksElement.EnumerateArray()
                    index += 1
                    Dim joins As New List(Of String)
                    For Each name In LinkEnds
                        Dim v As JsonElement
                        If e.TryGetProperty(name, v) AndAlso v.ValueKind = JsonValueKind.String Then joins.Add(v.GetString())
                    Next
                    linkList.Add(Identified(e, "link" & index.ToString(CultureInfo.InvariantCulture), joins))
                Next
            End If
            Return New SceneDoc(worldElement.GetRawText(), bodyList, linkList)
        End Using
    End Function

    Private Shared ReadOnly LinkEnds As String() = {"a", "b"}

    Private Shared Function Identified(e As JsonElement, defaultId As String, joins As IReadOnlyList(Of String)) As SceneItem
        Dim raw = e.GetRawText()
        Dim idElement As JsonElement
        If e.ValueKind = JsonValueKind.Object AndAlso e.TryGetProperty("id", idElement) AndAlso idElement.ValueKind = JsonValueKind.String Then
            Return New SceneItem(idElement.GetString(), raw, joins)
        End If
        If e.ValueKind <> JsonValueKind.Object Then Return New SceneItem(defaultId, raw, joins)
        Dim rest = raw.Substring(raw.IndexOf("{"c, StringComparison.Ordinal) + 1)
        Dim separator = If(rest.Trim() = "}", "", ", ")
        Return New SceneItem(defaultId, "{" & JsonText.Quote("id") & ": " & JsonText.Quote(defaultId) & separator & rest, joins)
    End Function
End Class
