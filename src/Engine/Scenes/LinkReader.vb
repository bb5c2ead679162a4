Option Strict On
Imports System.Globalization

Namespace Scenes
    ''' <summary>
    ''' Reads and checks a scene file's optional "links" array against bodies already read: each link's
    ''' fields, its two ends, and whether a rod or string fits between its ends as the file places them.
    ''' Every problem is one <see cref="SceneFormatException"/> naming the place ("links[2].b").
    ''' </summary>
    Friend Module LinkReader
        ''' <summary>How far a rod's length may differ from the distance between its ends in the file (or a string fall short of it), m.</summary>
        Friend Const LengthTolerance As Double = 0.000000001

        ''' <summary>The links, in file order; empty when the file has no "links".</summary>
        Friend Function ReadLinks(root As JsonFields, bodies As IReadOnlyList(Of BodySpec)) As List(Of LinkSpec)
            Dim links As New List(Of LinkSpec)
            Dim e = root.Find("links")
            If e Is Nothing Then Return links
            If JsonFields.JsonType(e) <> "array" Then Throw JsonFields.WrongType(e, "links", "an array")
            Dim byId As New Dictionary(Of String, BodySpec)(StringComparer.Ordinal)
            For Each b In bodies
                byId.Add(b.Id, b)
            Next
            ' link id -> index of the link that has it (links have their own ids, apart from the bodies')
            Dim owners As New Dictionary(Of String, Integer)(StringComparer.Ordinal)
            Dim index = 0
            For Each item In e.Elements()
                Dim place = LinkPlace(index)
                If JsonFields.JsonType(item) <> "object" Then Throw JsonFields.WrongType(item, place, "an object")
                Dim link = ReadLink(New JsonFields(item, place), index, owners, byId)
                owners.Add(link.Id, index)
                links.Add(link)
                index += 1
            Next
            Return links
        End Function

        ''' <summary>"links[2]": 0-based, as in a JSON path.</summary>
        Friend Function LinkPlace(index As Integer) As String
            Return "links[" & index.ToString(CultureInfo.InvariantCulture) & "]"
        End Function

        Private Function ReadLink(f As JsonFields, index As Integer, owners As Dictionary(Of String, Integer),
                                  byId As Dictionary(Of String, BodySpec)) As LinkSpec
            Dim place = LinkPlace(index)
            Dim typeName = f.RequiredString("type")
            Dim kind As LinkKind
            Select Case typeName
                Case "spring" : kind = LinkKind.Spring
                Case "rod" : kind = LinkKind.Rod
                Case "string" : kind = LinkKind.String
                Case Else
                    Throw New SceneFormatException(f.PlaceOf("type"), "unknown type """ & typeName & """ (expected ""spring"", ""rod"" or ""string"")")
            End Select
            Dim link As New LinkSpec With {.Index = index, .Kind = kind, .Id = SceneIds.ReadId(f, index, owners, "link", AddressOf LinkPlace)}
            link.A = ReadEnd(f, "a", byId)
            Dim hasB = f.Find("b") IsNot Nothing
            Dim hasAt = f.Find("at") IsNot Nothing
            If hasB AndAlso hasAt Then
                Throw New SceneFormatException(place, "has both ""b"" and ""at""; give one: the other end is a body (""b"") or a fixed point (""at"")")
            End If
            If Not hasB AndAlso Not hasAt Then
                Throw New SceneFormatException(place, "needs ""b"" (a body) or ""at"" (a fixed point [x, y]) for its other end")
            End If
            If hasB Then
                link.B = ReadEnd(f, "b", byId)
                If link.B Is link.A Then
                    Throw New SceneFormatException(f.PlaceOf("b"), "is """ & link.B.Id & """, the same body as a; a link joins two different bodies (use ""at"" for a fixed point)")
                End If
            Else
                link.Anchor = ReadPoint(f, "at")
            End If
            CheckMovable(f, link)
            ReadNumbers(f, link)
            Return link
        End Function

        ''' <summary>A body named by <paramref name="name"/> ("a" or "b"): it must exist and have a reference point.</summary>
        Private Function ReadEnd(f As JsonFields, name As String, byId As Dictionary(Of String, BodySpec)) As BodySpec
            Dim e = f.Require(name)
            If JsonFields.JsonType(e) <> "string" Then Throw JsonFields.WrongType(e, f.PlaceOf(name), "a body's id (a string)")
            Dim body As BodySpec = Nothing
            If Not byId.TryGetValue(e.Value, body) Then Throw New SceneFormatException(f.PlaceOf(name), "no body """ & e.Value & """")
            ' The format joins circles, rectangles and polygons at their centres; it gives a segment no such point.
            If body.Kind = ShapeKind.Segment Then
                Throw New SceneFormatException(f.PlaceOf(name), """" & body.Id & """ is a segment, which has no reference point to join (use ""at"" for a point on it)")
            End If
            Return body
        End Function

        ''' <summary>An [x, y] pair of finite numbers, m.</summary>
        Private Function ReadPoint(f As JsonFields, name As String) As Vector
            Dim place = f.PlaceOf(name)
            Dim e = f.Require(name)
            If JsonFields.JsonType(e) <> "array" Then Throw JsonFields.WrongType(e, place, "an [x, y] pair")
            Dim xy = e.Elements().ToList()
            If xy.Count <> 2 Then Throw New SceneFormatException(place, "must be an [x, y] pair, not " & xy.Count.ToString(CultureInfo.InvariantCulture) & " numbers")
            Return New Vector(JsonFields.Number(xy(0), place & "[0]"), JsonFields.Number(xy(1), place & "[1]"))
        End Function

        ''' <summary>End a must move; when it does not, says whether swapping the ends would help.</summary>
        Private Sub CheckMovable(f As JsonFields, link As LinkSpec)
            If Not link.A.IsFixed Then Return
            If link.B IsNot Nothing AndAlso Not link.B.IsFixed Then
                Throw New SceneFormatException(f.PlaceOf("a"), """" & link.A.Id & """ is fixed, but end a must be a movable body (swap a and b)")
            End If
            Dim other = If(link.B Is Nothing, "the point " & Point(link.Anchor), "body """ & link.B.Id & """")
            Throw New SceneFormatException(LinkPlace(link.Index), "both ends are fixed (body """ & link.A.Id & """ and " & other & "), so it could never move anything")
        End Sub

        ''' <summary>The numbers of the link's kind, with their defaults from the distance between its ends in the file.</summary>
        Private Sub ReadNumbers(f As JsonFields, link As LinkSpec)
            Dim endB = If(link.B Is Nothing, link.Anchor, link.B.ReferencePoint)
            ' Measured as Link.Distance measures it, so a default length is exactly the built link's distance.
            Dim distance = (endB - link.A.ReferencePoint).Length
            Dim kindName = If(link.Kind = LinkKind.Rod, "rod", "string")
            If link.Kind = LinkKind.Spring Then
                ' "length" on a spring is an easy slip for "rest_length"; ignoring it would silently use the distance.
                If f.Find("length") IsNot Nothing Then
                    Throw New SceneFormatException(f.PlaceOf("length"), "a spring has no ""length""; its natural length is ""rest_length""")
                End If
                link.Stiffness = Positive(f, "stiffness", f.RequiredNumber("stiffness"))
                link.Length = NotNegative(f, "rest_length", f.OptionalNumber("rest_length", distance))
                link.Damping = NotNegative(f, "damping", f.OptionalNumber("damping", 0.0))
                Return
            End If
            If f.Find("rest_length") IsNot Nothing Then
                Throw New SceneFormatException(f.PlaceOf("rest_length"), "a " & kindName & " has no ""rest_length""; its length is ""length""")
            End If
            If f.Find("length") Is Nothing Then
                If distance = 0 Then
                    Throw New SceneFormatException(LinkPlace(link.Index), "the " & kindName & "'s ends are at the same point in the file " & Point(endB) &
                        If(link.Kind = LinkKind.Rod, ", so it would have length 0", ", so it needs a ""length"" greater than 0"))
                End If
                link.Length = distance
                Return
            End If
            link.Length = Positive(f, "length", f.RequiredNumber("length"))
            Dim distanceText As String = Nothing, lengthText As String = Nothing
            SceneReader.Distinct(distance, link.Length, distanceText, lengthText)
            If link.Kind = LinkKind.Rod AndAlso Math.Abs(link.Length - distance) > LengthTolerance Then
                Throw New SceneFormatException(f.PlaceOf("length"), "a rod's length must be the distance between its ends in the file, " & distanceText &
                    " m, not " & lengthText & " m (they differ by " & SceneReader.Brief(Math.Abs(link.Length - distance)) &
                    " m; leave ""length"" out to use the distance)")
            End If
            If link.Kind = LinkKind.String AndAlso link.Length < distance - LengthTolerance Then
                Throw New SceneFormatException(f.PlaceOf("length"), "a string of " & lengthText & " m cannot reach between its ends, which are " &
                    distanceText & " m apart in the file (" & SceneReader.Brief(distance - link.Length) & " m too short)")
            End If
        End Sub

        ''' <summary>"(x = 2, y = 3)".</summary>
        Private Function Point(p As Vector) As String
            Return "(x = " & SceneReader.Brief(p.X) & ", y = " & SceneReader.Brief(p.Y) & ")"
        End Function

        Private Function Positive(f As JsonFields, name As String, value As Double) As Double
            If Not (value > 0) Then Throw New SceneFormatException(f.PlaceOf(name), "must be greater than 0")
            Return value
        End Function

        Private Function NotNegative(f As JsonFields, name As String, value As Double) As Double
            If Not (value >= 0) Then Throw New SceneFormatException(f.PlaceOf(name), "must be 0 or greater")
            Return value
        End Function

    End Module
End Namespace
