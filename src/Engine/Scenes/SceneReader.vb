Option Strict On
Imports System.Globalization
Imports System.Runtime.Serialization.Json
Imports System.Text
Imports System.Text.RegularExpressions
Imports System.Xml
Imports System.Xml.Linq

Namespace Scenes
    ''' <summary>
    ''' Reads a physics-scene/1 document: parse, check every field, check ids, walls and overlaps, then
    ''' the links between the bodies, and only then build the world, so an error never leaves anything
    ''' half-loaded.
    ''' </summary>
    Friend Module SceneReader
        ''' <summary>The only format this reader knows.</summary>
        Friend Const FormatName As String = "physics-scene/1"

        ''' <summary>How far a movable circle may stick out of a walled container, m: rounding in hand-typed sums (0.1 + 0.2).</summary>
        Private Const WallTolerance As Double = 0.000000001

        Private ReadOnly ColorPattern As New Regex("^#[0-9a-fA-F]{6}$", RegexOptions.CultureInvariant)

        Friend Function Read(text As String) As World
            If text Is Nothing Then Throw New ArgumentNullException(NameOf(text))
            Dim root = New JsonFields(ParseJson(text), "")
            CheckFormat(root)
            Dim settings = ReadWorld(root)
            Dim liquids As New List(Of LiquidSpec)
            Dim bodies = ReadBodies(root, settings, liquids)
            If settings.Walls Then CheckInside(bodies, settings)
            OverlapCheck.Check(bodies)
            CheckLiquids(liquids)
            Dim links = LinkReader.ReadLinks(root, bodies)
            Return Build(settings, bodies, liquids, links)
        End Function

        ''' <summary>"bodies[3]": 0-based, as in a JSON path.</summary>
        Friend Function BodyPlace(index As Integer) As String
            Return "bodies[" & index.ToString(CultureInfo.InvariantCulture) & "]"
        End Function

        Private Function ParseJson(text As String) As XElement
            If text.Length > 0 AndAlso text(0) = ChrW(&HFEFF) Then text = text.Substring(1)
            If text.Trim().Length = 0 Then Throw New SceneFormatException("document", "is empty, not JSON")
            Dim element As XElement
            Try
                Using reader = JsonReaderWriterFactory.CreateJsonReader(Encoding.UTF8.GetBytes(text), ReaderQuotas)
                    element = XElement.Load(reader)
                End Using
            Catch ex As XmlException
                Throw New SceneFormatException("document", "is not valid JSON (" & OneLine(ex.Message) & ")", ex)
            Catch ex As InvalidOperationException
                Throw New SceneFormatException("document", "is not valid JSON (" & OneLine(ex.Message) & ")", ex)
            Catch ex As FormatException
                ' A raw control character inside a string.
                Throw New SceneFormatException("document", "is not valid JSON (" & OneLine(ex.Message) & ")", ex)
            End Try
            If JsonFields.JsonType(element) <> "object" Then Throw JsonFields.WrongType(element, "document", "a JSON object")
            CheckComplete(text)
            Return element
        End Function

        ''' <summary>
        ''' No limit on text or array sizes (scenes of 100 000 bodies), but a nesting limit: a scene is a
        ''' few levels deep, and 100 000 nested brackets would otherwise take half a minute to reject.
        ''' </summary>
        Private ReadOnly ReaderQuotas As New XmlDictionaryReaderQuotas() With {
            .MaxDepth = 64, .MaxStringContentLength = Integer.MaxValue, .MaxArrayLength = Integer.MaxValue,
            .MaxBytesPerRead = Integer.MaxValue, .MaxNameTableCharCount = Integer.MaxValue}

        ''' <summary>
        ''' The BCL reader closes open objects silently when the text ends after a number, and stops
        ''' reading at the root's end: a truncated file (a crash while saving) or trailing text would
        ''' pass. This is not a parser, only a count of brackets outside strings: the root object must
        ''' close exactly at the last non-blank character.
        ''' </summary>
        Private Sub CheckComplete(text As String)
            Dim depth = 0
            Dim inString = False
            Dim escaped = False
            Dim closedAt = -1
            Dim last = " "c ' the last non-blank character outside strings
            For i = 0 To text.Length - 1
                Dim ch = text(i)
                If inString Then
                    If escaped Then
                        escaped = False
                    ElseIf ch = "\"c Then
                        escaped = True
                    ElseIf ch = """"c Then
                        inString = False
                        last = ch
                    End If
                    Continue For
                End If
                If closedAt >= 0 Then
                    If Not Char.IsWhiteSpace(ch) Then Throw New SceneFormatException("document", "is not valid JSON (there is more text after its closing '}', at character " & (i + 1).ToString(CultureInfo.InvariantCulture) & ")")
                    Continue For
                End If
                Select Case ch
                    Case """"c : inString = True
                    Case "{"c, "["c : depth += 1
                    Case "}"c, "]"c
                        ' The BCL reader lets a comma before the root's last '}' through.
                        If last = ","c Then Throw New SceneFormatException("document", "is not valid JSON (a comma before '" & ch & "' at character " & (i + 1).ToString(CultureInfo.InvariantCulture) & ")")
                        depth -= 1
                        If depth = 0 Then closedAt = i
                End Select
                If Not Char.IsWhiteSpace(ch) Then last = ch
            Next
            If closedAt < 0 Then Throw New SceneFormatException("document", "is not valid JSON (it ends before its closing '}': is the file complete?)")
        End Sub

        Private Function OneLine(message As String) As String
            Return String.Join(" ", message.Split({ChrW(13), ChrW(10)}, StringSplitOptions.RemoveEmptyEntries)).Trim()
        End Function

        Private Sub CheckFormat(root As JsonFields)
            Dim e = root.Find("format")
            If e Is Nothing Then Throw New SceneFormatException("format", "is required (""" & FormatName & """)")
            If JsonFields.JsonType(e) <> "string" Then Throw JsonFields.WrongType(e, "format", """" & FormatName & """")
            If e.Value <> FormatName Then Throw New SceneFormatException("format", "must be """ & FormatName & """, not """ & e.Value & """")
        End Sub

        Private Function ReadWorld(root As JsonFields) As WorldSettings
            Dim e = root.Require("world")
            If JsonFields.JsonType(e) <> "object" Then Throw JsonFields.WrongType(e, "world", "an object")
            Dim f As New JsonFields(e, "world")
            Dim s As New WorldSettings With {
                .Width = Positive(f, "width", f.RequiredNumber("width")),
                .Height = Positive(f, "height", f.RequiredNumber("height")),
                .Gravity = f.OptionalNumber("gravity", 9.81),
                .Restitution = f.OptionalNumber("restitution", 1.0),
                .Walls = f.OptionalBoolean("walls", True)}
            If s.Gravity < 0 Then Throw New SceneFormatException("world.gravity", "must be 0 or greater")
            If s.Restitution < 0 OrElse s.Restitution > 1 Then Throw New SceneFormatException("world.restitution", "must be between 0 and 1")
            s.Friction = If(OptionalCoefficient(f, "friction"), 0.0)
            s.StaticFriction = OptionalCoefficient(f, "static_friction")
            If s.StaticFriction.HasValue AndAlso s.StaticFriction.Value < s.Friction Then
                Throw New SceneFormatException("world.static_friction", "must be at least friction (" & Brief(s.Friction) & "), not " & Brief(s.StaticFriction.Value))
            End If
            s.AirDensity = If(OptionalCoefficient(f, "air_density"), 0.0)
            Return s
        End Function

        Private Function Positive(f As JsonFields, name As String, value As Double) As Double
            If Not (value > 0) Then Throw New SceneFormatException(f.PlaceOf(name), "must be greater than 0")
            Return value
        End Function

        ''' <summary>An optional coefficient of friction or drag (a density of air): a finite number ≥ 0, or Nothing when absent.</summary>
        Private Function OptionalCoefficient(f As JsonFields, name As String) As Double?
            If f.Find(name) Is Nothing Then Return Nothing
            Dim value = f.RequiredNumber(name)
            If value < 0 Then Throw New SceneFormatException(f.PlaceOf(name), "must be 0 or greater")
            Return value
        End Function

        ''' <summary>
        ''' The entries of "bodies": the bodies, in file order, and the liquid regions (entries of type "liquid",
        ''' which share the bodies' ids and places but never collide) into <paramref name="liquids"/>.
        ''' </summary>
        Private Function ReadBodies(root As JsonFields, settings As WorldSettings, liquids As List(Of LiquidSpec)) As List(Of BodySpec)
            Dim e = root.Require("bodies")
            If JsonFields.JsonType(e) <> "array" Then Throw JsonFields.WrongType(e, "bodies", "an array")
            Dim bodies As New List(Of BodySpec)
            ' id -> index of the body that has it
            Dim owners As New Dictionary(Of String, Integer)(StringComparer.Ordinal)
            Dim index = 0
            For Each item In e.Elements()
                Dim place = BodyPlace(index)
                If JsonFields.JsonType(item) <> "object" Then Throw JsonFields.WrongType(item, place, "an object")
                Dim f As New JsonFields(item, place)
                If IsLiquid(f) Then
                    Dim liquid = ReadLiquid(f, index, owners)
                    owners.Add(liquid.Id, index)
                    liquids.Add(liquid)
                Else
                    Dim body = ReadBody(f, index, owners, settings)
                    owners.Add(body.Id, index)
                    bodies.Add(body)
                End If
                index += 1
            Next
            Return bodies
        End Function

        ''' <summary>Whether the entry's "type" is the string "liquid" (anything else is read, and checked, as a body).</summary>
        Private Function IsLiquid(f As JsonFields) As Boolean
            Dim e = f.Find("type")
            Return e IsNot Nothing AndAlso JsonFields.JsonType(e) = "string" AndAlso e.Value = "liquid"
        End Function

        ''' <summary>A liquid region: its rectangle, density (&gt; 0), drag coefficients (≥ 0) and colour.</summary>
        Private Function ReadLiquid(f As JsonFields, index As Integer, owners As Dictionary(Of String, Integer)) As LiquidSpec
            Dim liquid As New LiquidSpec With {.Index = index, .Id = SceneIds.ReadId(f, index, owners, "", AddressOf BodyPlace)}
            liquid.X = f.RequiredNumber("x")
            liquid.Y = f.RequiredNumber("y")
            liquid.Width = Positive(f, "width", f.RequiredNumber("width"))
            liquid.Height = Positive(f, "height", f.RequiredNumber("height"))
            liquid.Density = Positive(f, "density", f.RequiredNumber("density"))
            liquid.DragCoefficient = If(OptionalCoefficient(f, "drag_coefficient"), 0.0)
            liquid.LinearDrag = If(OptionalCoefficient(f, "linear_drag"), 0.0)
            liquid.Color = ReadColor(f)
            Return liquid
        End Function

        ''' <summary>Liquids may not overlap each other (touching is fine): the later of the first overlapping pair is named.</summary>
        Private Sub CheckLiquids(liquids As List(Of LiquidSpec))
            For j = 1 To liquids.Count - 1
                Dim b = liquids(j)
                For i = 0 To j - 1
                    Dim a = liquids(i)
                    If Math.Min(a.X + a.Width, b.X + b.Width) > Math.Max(a.X, b.X) AndAlso Math.Min(a.Y + a.Height, b.Y + b.Height) > Math.Max(a.Y, b.Y) Then
                        Throw New SceneFormatException(b.Place, "overlaps the liquid " & a.Place & " (liquids may not overlap each other)")
                    End If
                Next
            Next
        End Sub

        ''' <summary>
        ''' A body's own surface (friction, static_friction: any body, circles included, which keep them but take no
        ''' friction) and a movable body's drag (drag_coefficient, linear_drag; on a fixed body checked and ignored).
        ''' </summary>
        Private Sub ReadForces(f As JsonFields, body As BodySpec, settings As WorldSettings)
            body.Friction = OptionalCoefficient(f, "friction")
            body.StaticFriction = OptionalCoefficient(f, "static_friction")
            Dim kinetic = If(body.Friction, settings.Friction)
            If body.StaticFriction.HasValue AndAlso body.StaticFriction.Value < kinetic Then
                Throw New SceneFormatException(f.PlaceOf("static_friction"), "must be at least " & If(body.Friction.HasValue, "its friction", "world.friction") &
                                               " (" & Brief(kinetic) & "), not " & Brief(body.StaticFriction.Value))
            End If
            Dim dragCoefficient = OptionalCoefficient(f, "drag_coefficient")
            Dim linearDrag = OptionalCoefficient(f, "linear_drag")
            If Not body.IsFixed Then
                body.DragCoefficient = If(dragCoefficient, 0.0)
                body.LinearDrag = If(linearDrag, 0.0)
            End If
        End Sub

        ''' <summary>An optional "color": "#rrggbb", or Nothing.</summary>
        Private Function ReadColor(f As JsonFields) As String
            Dim color = f.OptionalString("color")
            If color IsNot Nothing AndAlso Not ColorPattern.IsMatch(color) Then
                Throw New SceneFormatException(f.PlaceOf("color"), "must be a colour ""#rrggbb"" such as ""#e53935"", not """ & color & """")
            End If
            Return color
        End Function

        Private Function ReadBody(f As JsonFields, index As Integer, owners As Dictionary(Of String, Integer), settings As WorldSettings) As BodySpec
            Dim typeName = f.RequiredString("type")
            Dim kind As ShapeKind
            Select Case typeName
                Case "circle" : kind = ShapeKind.Circle
                Case "rectangle" : kind = ShapeKind.Rectangle
                Case "segment" : kind = ShapeKind.Segment
                Case "polygon" : kind = ShapeKind.Polygon
                Case Else
                    Throw New SceneFormatException(f.PlaceOf("type"), "unknown type """ & typeName & """ (expected ""circle"", ""rectangle"", ""segment"", ""polygon"" or ""liquid"")")
            End Select
            Dim body As New BodySpec With {.Index = index, .Kind = kind, .Id = SceneIds.ReadId(f, index, owners, "", AddressOf BodyPlace)}
            Select Case kind
                Case ShapeKind.Circle
                    body.X = f.RequiredNumber("x")
                    body.Y = f.RequiredNumber("y")
                    body.Radius = Positive(f, "radius", f.RequiredNumber("radius"))
                    ReadMotion(f, body, fixedByDefault:=False)
                    body.Outline = Outline.Point(body.Radius)
                    body.Position = New Vector(body.X, body.Y)
                Case ShapeKind.Rectangle
                    body.X = f.RequiredNumber("x")
                    body.Y = f.RequiredNumber("y")
                    body.Width = Positive(f, "width", f.RequiredNumber("width"))
                    body.Height = Positive(f, "height", f.RequiredNumber("height"))
                    ReadMotion(f, body, fixedByDefault:=True)
                    body.Outline = Outline.Box(body.Width, body.Height)
                    body.Position = New Vector(body.X, body.Y)
                Case ShapeKind.Segment
                    body.X = f.RequiredNumber("x1")
                    body.Y = f.RequiredNumber("y1")
                    body.X2 = f.RequiredNumber("x2")
                    body.Y2 = f.RequiredNumber("y2")
                    body.IsFixed = True
                    If body.X = body.X2 AndAlso body.Y = body.Y2 Then
                        Throw New SceneFormatException(body.Place, "a segment's two ends must differ (both are at x = " & Brief(body.X) & ", y = " & Brief(body.Y) & ")")
                    End If
                    body.Outline = Outline.Segment(Vector.Zero, New Vector(body.X2 - body.X, body.Y2 - body.Y))
                    body.Position = New Vector(body.X, body.Y)
                Case Else
                    body.Vertices = ReadVertices(f)
                    Dim core As Outline
                    Try
                        core = Outline.Polygon(body.Vertices)
                    Catch ex As ArgumentException
                        Throw New SceneFormatException(f.PlaceOf("vertices"), PolygonProblem(ex.Message), ex)
                    End Try
                    ReadMotion(f, body, fixedByDefault:=False)
                    body.Position = core.Centroid
                    body.Outline = core.Translated(-core.Centroid)
                    body.X = body.Position.X
                    body.Y = body.Position.Y
            End Select
            body.Color = ReadColor(f)
            ReadForces(f, body, settings)
            Return body
        End Function

        ''' <summary>
        ''' "fixed", "mass", "vx", "vy" of a body that may move. A fixed body's mass and velocity mean
        ''' nothing, but a wrong one is still a mistake worth naming.
        ''' </summary>
        Private Sub ReadMotion(f As JsonFields, body As BodySpec, fixedByDefault As Boolean)
            body.IsFixed = f.OptionalBoolean("fixed", fixedByDefault)
            If body.IsFixed Then
                If f.Find("mass") IsNot Nothing Then Positive(f, "mass", f.RequiredNumber("mass"))
            Else
                body.Mass = Positive(f, "mass", f.RequiredNumber("mass"))
            End If
            Dim vx = f.OptionalNumber("vx", 0.0)
            Dim vy = f.OptionalNumber("vy", 0.0)
            If Not body.IsFixed Then
                body.Vx = vx
                body.Vy = vy
            End If
        End Sub

        ''' <summary>A polygon's "vertices": an array of at least 3 [x, y] pairs of finite numbers.</summary>
        Private Function ReadVertices(f As JsonFields) As IReadOnlyList(Of Vector)
            Dim place = f.PlaceOf("vertices")
            Dim e = f.Require("vertices")
            If JsonFields.JsonType(e) <> "array" Then Throw JsonFields.WrongType(e, place, "an array of [x, y] pairs")
            Dim corners As New List(Of Vector)
            Dim k = 0
            For Each item In e.Elements()
                Dim itemPlace = place & "[" & k.ToString(CultureInfo.InvariantCulture) & "]"
                If JsonFields.JsonType(item) <> "array" Then Throw JsonFields.WrongType(item, itemPlace, "an [x, y] pair")
                Dim xy = item.Elements().ToList()
                If xy.Count <> 2 Then Throw New SceneFormatException(itemPlace, "must be an [x, y] pair, not " & xy.Count.ToString(CultureInfo.InvariantCulture) & " numbers")
                corners.Add(New Vector(JsonFields.Number(xy(0), itemPlace & "[0]"), JsonFields.Number(xy(1), itemPlace & "[1]")))
                k += 1
            Next
            If corners.Count < 3 Then
                Throw New SceneFormatException(place, "a polygon needs at least 3 corners, not " & corners.Count.ToString(CultureInfo.InvariantCulture))
            End If
            Return corners
        End Function

        ''' <summary>The geometry's reason, as the reader says it.</summary>
        Private Function PolygonProblem(message As String) As String
            If message.Contains("not convex") OrElse message.Contains("intersects itself") Then Return "the polygon is not convex (its corners must go round it once, turning the same way at every corner)"
            If message.Contains("zero area") Then Return "the polygon has zero area"
            If message.Contains("distinct corners") Then Return "a polygon needs at least 3 distinct corners"
            Return message
        End Function

        Private Sub CheckInside(bodies As List(Of BodySpec), s As WorldSettings)
            For Each b In bodies
                If b.IsFixed Then Continue For
                Dim where As String = Nothing
                If b.Kind = ShapeKind.Circle Then
                    If b.X - b.Radius < -WallTolerance Then
                        where = "on the left (x - radius = " & Brief(b.X - b.Radius) & " m < 0)"
                    ElseIf b.X + b.Radius > s.Width + WallTolerance Then
                        where = "on the right (x + radius = " & Brief(b.X + b.Radius) & " m > width = " & Brief(s.Width) & " m)"
                    ElseIf b.Y - b.Radius < -WallTolerance Then
                        where = "at the bottom (y - radius = " & Brief(b.Y - b.Radius) & " m < 0)"
                    ElseIf b.Y + b.Radius > s.Height + WallTolerance Then
                        where = "at the top (y + radius = " & Brief(b.Y + b.Radius) & " m > height = " & Brief(s.Height) & " m)"
                    End If
                ElseIf b.MinX < -WallTolerance Then
                    where = "on the left (its left side is at x = " & Brief(b.MinX) & " m < 0)"
                ElseIf b.MaxX > s.Width + WallTolerance Then
                    where = "on the right (its right side is at x = " & Brief(b.MaxX) & " m > width = " & Brief(s.Width) & " m)"
                ElseIf b.MinY < -WallTolerance Then
                    where = "at the bottom (its bottom is at y = " & Brief(b.MinY) & " m < 0)"
                ElseIf b.MaxY > s.Height + WallTolerance Then
                    where = "at the top (its top is at y = " & Brief(b.MaxY) & " m > height = " & Brief(s.Height) & " m)"
                End If
                If where IsNot Nothing Then
                    Throw New SceneFormatException(b.Place, "is not wholly inside the container: it sticks out " & where)
                End If
            Next
        End Sub

        ''' <summary>A number for a message: short, invariant.</summary>
        Friend Function Brief(value As Double) As String
            Return value.ToString("G6", CultureInfo.InvariantCulture)
        End Function

        ''' <summary>
        ''' Two values for a message that compares them: briefly, or in full where brief they would read the same
        ''' ("1078.02 m, not 1078.02 m" says nothing).
        ''' </summary>
        Friend Sub Distinct(first As Double, second As Double, ByRef firstText As String, ByRef secondText As String)
            firstText = Brief(first)
            secondText = Brief(second)
            If firstText = secondText Then
                firstText = first.ToString("R", CultureInfo.InvariantCulture)
                secondText = second.ToString("R", CultureInfo.InvariantCulture)
            End If
        End Sub

        Private Function Build(s As WorldSettings, bodies As List(Of BodySpec), liquids As List(Of LiquidSpec), links As List(Of LinkSpec)) As World
            Dim w As New World(s.Width, s.Height, s.Gravity, s.Restitution, s.Walls) With {
                .Friction = s.Friction, .StaticFriction = s.StaticFriction, .AirDensity = s.AirDensity}
            Dim shapes As New List(Of Shape)(bodies.Count)
            For Each b In bodies
                Dim shape = b.ToShape()
                w.Add(shape)
                shapes.Add(shape)
            Next
            For Each l In liquids
                w.Add(l.ToLiquid())
            Next
            For Each l In links
                w.Add(l.ToLink(shapes))
            Next
            Return w
        End Function
    End Module
End Namespace
