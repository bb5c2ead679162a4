Option Strict On
Imports System.Text.Json

''' <summary>
''' An independent reading of the physics-scene/1 specification, for the body kinds the engine does not
''' read yet (segments, polygons, movable boxes, links): fields, ranges, convexity, containment and
''' overlaps, checked exactly (separating axes for convex shapes), as the specification states them.
''' </summary>
Public Module SpecConformance
    Private Const Slack As Double = 0.000000001

    ''' <summary>A body as geometry: a circle, or a convex outline (a segment is a two-corner outline).</summary>
    Private NotInheritable Class Solid
        Public Id As String
        Public IsFixed As Boolean
        Public IsCircle As Boolean
        Public Centre As (X As Double, Y As Double)
        Public Radius As Double
        Public Corners As List(Of (X As Double, Y As Double))
        Public Reference As (X As Double, Y As Double)
    End Class

    ''' <summary>Every way the text breaks the specification; empty when it conforms.</summary>
    Public Function Problems(text As String) As List(Of String)
        Dim found As New List(Of String)
        Using doc = JsonDocument.Parse(text)
            Dim root = doc.RootElement
            If Str(root, "format") <> "physics-scene/1" Then found.Add("format")
            Dim world = root.GetProperty("world")
            Dim width = Num(world, "width"), height = Num(world, "height")
            If Not (width > 0 AndAlso height > 0) Then found.Add("world size")
            If Num(world, "gravity", 9.81) < 0 Then found.Add("gravity")
            Dim e = Num(world, "restitution", 1)
            If e < 0 OrElse e > 1 Then found.Add("restitution")
            Dim walls = Bool(world, "walls", True)
            Dim solids As New List(Of Solid)
            Dim ids As New HashSet(Of String)(StringComparer.Ordinal)
            Dim index = 0
            For Each b In root.GetProperty("bodies").EnumerateArray()
                index += 1
                Dim s = ReadBody(b, index, found)
                If s Is Nothing Then Continue For
                If Not ids.Add(s.Id) Then found.Add("id " & s.Id & " repeats")
                solids.Add(s)
            Next
            For Each s In solids
                If walls AndAlso Not s.IsFixed AndAlso Not Inside(s, width, height) Then found.Add(s.Id & " is not inside the container")
            Next
            For i = 0 To solids.Count - 1
                For j = i + 1 To solids.Count - 1
                    If solids(i).IsFixed AndAlso solids(j).IsFixed Then Continue For
                    Dim depth = OverlapDepth(solids(i), solids(j))
                    If depth > Slack Then found.Add(solids(i).Id & " and " & solids(j).Id & " overlap by " & depth.ToString("G6", Globalization.CultureInfo.InvariantCulture) & " m")
                Next
            Next
            Dim links As JsonElement
            If root.TryGetProperty("links", links) Then CheckLinks(links, solids, found)
        End Using
        Return found
    End Function

    Private Function ReadBody(b As JsonElement, index As Integer, found As List(Of String)) As Solid
        Dim s As New Solid With {.Id = Str(b, "id", index.ToString(Globalization.CultureInfo.InvariantCulture))}
        If s.Id.Length = 0 Then found.Add("empty id")
        Select Case Str(b, "type")
            Case "circle"
                s.IsCircle = True
                s.Centre = (Num(b, "x"), Num(b, "y"))
                s.Radius = Num(b, "radius")
                s.IsFixed = Bool(b, "fixed", False)
                s.Reference = s.Centre
                If Not (s.Radius > 0) Then found.Add(s.Id & ": radius")
            Case "rectangle"
                Dim x = Num(b, "x"), y = Num(b, "y"), w = Num(b, "width"), h = Num(b, "height")
                If Not (w > 0 AndAlso h > 0) Then found.Add(s.Id & ": size")
                s.IsFixed = Bool(b, "fixed", True)
                s.Corners = New List(Of (X As Double, Y As Double)) From {(x, y), (x + w, y), (x + w, y + h), (x, y + h)}
                s.Reference = (x + w / 2, y + h / 2)
            Case "segment"
                s.IsFixed = True
                s.Corners = New List(Of (X As Double, Y As Double)) From {(Num(b, "x1"), Num(b, "y1")), (Num(b, "x2"), Num(b, "y2"))}
                If s.Corners(0).Equals(s.Corners(1)) Then found.Add(s.Id & ": equal ends")
                s.Reference = ((s.Corners(0).X + s.Corners(1).X) / 2, (s.Corners(0).Y + s.Corners(1).Y) / 2)
            Case "polygon"
                s.IsFixed = Bool(b, "fixed", False)
                s.Corners = b.GetProperty("vertices").EnumerateArray().Select(Function(v) (v(0).GetDouble(), v(1).GetDouble())).ToList()
                If s.Corners.Count < 3 OrElse Not IsConvex(s.Corners) Then found.Add(s.Id & ": not a convex polygon with area")
                s.Reference = Centroid(s.Corners)
            Case Else
                found.Add("bodies[" & (index - 1).ToString(Globalization.CultureInfo.InvariantCulture) & "]: unknown type")
                Return Nothing
        End Select
        If Not s.IsFixed AndAlso Not (Num(b, "mass") > 0) Then found.Add(s.Id & ": a movable body needs a mass > 0")
        Return s
    End Function

    Private Sub CheckLinks(links As JsonElement, solids As List(Of Solid), found As List(Of String))
        Dim byId = solids.ToDictionary(Function(s) s.Id, StringComparer.Ordinal)
        Dim ids As New HashSet(Of String)(StringComparer.Ordinal)
        Dim index = 0
        For Each l In links.EnumerateArray()
            index += 1
            Dim id = Str(l, "id", "link" & index.ToString(Globalization.CultureInfo.InvariantCulture))
            If Not ids.Add(id) Then found.Add("link id " & id & " repeats")
            Dim type = Str(l, "type")
            If type <> "spring" AndAlso type <> "rod" AndAlso type <> "string" Then found.Add(id & ": type")
            Dim a As Solid = Nothing
            If Not byId.TryGetValue(Str(l, "a"), a) OrElse a.IsFixed Then
                found.Add(id & ": a must name a movable body")
                Continue For
            End If
            Dim hasB = l.TryGetProperty("b", Nothing)
            Dim hasAt = l.TryGetProperty("at", Nothing)
            If hasB = hasAt Then
                found.Add(id & ": exactly one of b and at")
                Continue For
            End If
            Dim other As (X As Double, Y As Double)
            If hasB Then
                Dim b As Solid = Nothing
                If Not byId.TryGetValue(Str(l, "b"), b) Then
                    found.Add(id & ": b names no body")
                    Continue For
                End If
                If b.IsCircle = False AndAlso b.Corners.Count = 2 Then found.Add(id & ": a segment has no reference point")
                other = b.Reference
            Else
                Dim at = l.GetProperty("at")
                other = (at(0).GetDouble(), at(1).GetDouble())
            End If
            Dim distance = Math.Sqrt((other.X - a.Reference.X) ^ 2 + (other.Y - a.Reference.Y) ^ 2)
            Select Case type
                Case "spring"
                    If Not (Num(l, "stiffness") > 0) Then found.Add(id & ": stiffness")
                    If Num(l, "rest_length", 0) < 0 OrElse Num(l, "damping", 0) < 0 Then found.Add(id & ": rest_length or damping")
                Case "rod"
                    If Math.Abs(Num(l, "length", distance) - distance) > Slack Then found.Add(id & ": a rod's length must be the distance in the file")
                Case "string"
                    If Num(l, "length", distance) < distance - Slack Then found.Add(id & ": a string shorter than the distance in the file")
            End Select
            If (type = "rod" OrElse type = "string") AndAlso Not (Num(l, "length", distance) > 0) Then found.Add(id & ": length")
        Next
    End Sub

    Private Function Inside(s As Solid, width As Double, height As Double) As Boolean
        If s.IsCircle Then
            Return s.Centre.X - s.Radius >= -Slack AndAlso s.Centre.X + s.Radius <= width + Slack AndAlso
                s.Centre.Y - s.Radius >= -Slack AndAlso s.Centre.Y + s.Radius <= height + Slack
        End If
        Return s.Corners.All(Function(p) p.X >= -Slack AndAlso p.Y >= -Slack AndAlso p.X <= width + Slack AndAlso p.Y <= height + Slack)
    End Function

    ''' <summary>How deep two bodies overlap, m (≤ 0 when apart or touching).</summary>
    Private Function OverlapDepth(a As Solid, b As Solid) As Double
        If a.IsCircle AndAlso b.IsCircle Then
            Return a.Radius + b.Radius - Math.Sqrt((a.Centre.X - b.Centre.X) ^ 2 + (a.Centre.Y - b.Centre.Y) ^ 2)
        End If
        If a.IsCircle Then Return CircleOutlineDepth(a, b.Corners)
        If b.IsCircle Then Return CircleOutlineDepth(b, a.Corners)
        Return OutlineDepth(a.Corners, b.Corners)
    End Function

    Private Function CircleOutlineDepth(c As Solid, corners As List(Of (X As Double, Y As Double))) As Double
        Dim nearest = Double.PositiveInfinity
        Dim edges = If(corners.Count = 2, 1, corners.Count)
        For i = 0 To edges - 1
            Dim p = corners(i), q = corners((i + 1) Mod corners.Count)
            Dim dx = q.X - p.X, dy = q.Y - p.Y
            Dim u = Math.Min(Math.Max(((c.Centre.X - p.X) * dx + (c.Centre.Y - p.Y) * dy) / (dx * dx + dy * dy), 0), 1)
            nearest = Math.Min(nearest, Math.Sqrt((c.Centre.X - p.X - u * dx) ^ 2 + (c.Centre.Y - p.Y - u * dy) ^ 2))
        Next
        If corners.Count > 2 AndAlso ContainsPoint(corners, c.Centre) Then Return c.Radius + nearest
        Return c.Radius - nearest
    End Function

    ''' <summary>Separating axes: the smallest overlap of the two outlines' projections on every edge normal, m.</summary>
    Private Function OutlineDepth(a As List(Of (X As Double, Y As Double)), b As List(Of (X As Double, Y As Double))) As Double
        Dim least = Double.PositiveInfinity
        For Each outline In {a, b}
            Dim edges = If(outline.Count = 2, 1, outline.Count)
            For i = 0 To edges - 1
                Dim p = outline(i), q = outline((i + 1) Mod outline.Count)
                Dim nx = -(q.Y - p.Y), ny = q.X - p.X
                Dim len = Math.Sqrt(nx * nx + ny * ny)
                nx /= len
                ny /= len
                Dim aMin = a.Min(Function(v) v.X * nx + v.Y * ny), aMax = a.Max(Function(v) v.X * nx + v.Y * ny)
                Dim bMin = b.Min(Function(v) v.X * nx + v.Y * ny), bMax = b.Max(Function(v) v.X * nx + v.Y * ny)
                least = Math.Min(least, Math.Min(aMax, bMax) - Math.Max(aMin, bMin))
            Next
        Next
        Return least
    End Function

    Private Function ContainsPoint(corners As List(Of (X As Double, Y As Double)), p As (X As Double, Y As Double)) As Boolean
        Dim sign = 0
        For i = 0 To corners.Count - 1
            Dim a = corners(i), b = corners((i + 1) Mod corners.Count)
            Dim cross = (b.X - a.X) * (p.Y - a.Y) - (b.Y - a.Y) * (p.X - a.X)
            Dim s = Math.Sign(cross)
            If s = 0 Then Return False
            If sign = 0 Then sign = s
            If s <> sign Then Return False
        Next
        Return True
    End Function

    ''' <summary>Every turn the same way, none straight, and one full turn in all (so not a star).</summary>
    Private Function IsConvex(corners As List(Of (X As Double, Y As Double))) As Boolean
        Dim sign = 0
        Dim turning = 0.0
        For i = 0 To corners.Count - 1
            Dim a = corners(i), b = corners((i + 1) Mod corners.Count), c = corners((i + 2) Mod corners.Count)
            Dim ux = b.X - a.X, uy = b.Y - a.Y, vx = c.X - b.X, vy = c.Y - b.Y
            Dim cross = ux * vy - uy * vx
            If cross = 0 Then Return False
            If sign = 0 Then sign = Math.Sign(cross)
            If Math.Sign(cross) <> sign Then Return False
            turning += Math.Atan2(cross, ux * vx + uy * vy)
        Next
        Return Math.Abs(Math.Abs(turning) - 2 * Math.PI) < 0.000001
    End Function

    ''' <summary>The centre of area (shoelace formula), measured from the first corner: from the origin, a small polygon a kilometre out loses microns to rounding.</summary>
    Private Function Centroid(corners As List(Of (X As Double, Y As Double))) As (X As Double, Y As Double)
        Dim o = corners(0)
        Dim a2 = 0.0, cx = 0.0, cy = 0.0
        For i = 0 To corners.Count - 1
            Dim p = (X:=corners(i).X - o.X, Y:=corners(i).Y - o.Y)
            Dim q = (X:=corners((i + 1) Mod corners.Count).X - o.X, Y:=corners((i + 1) Mod corners.Count).Y - o.Y)
            Dim cross = p.X * q.Y - q.X * p.Y
            a2 += cross
            cx += (p.X + q.X) * cross
            cy += (p.Y + q.Y) * cross
        Next
        Return (o.X + cx / (3 * a2), o.Y + cy / (3 * a2))
    End Function

    Private Function Num(e As JsonElement, name As String, Optional fallback As Double = Double.NaN) As Double
        Dim v As JsonElement
        If Not e.TryGetProperty(name, v) Then Return fallback
        Return v.GetDouble()
    End Function

    Private Function Str(e As JsonElement, name As String, Optional fallback As String = "") As String
        Dim v As JsonElement
        If Not e.TryGetProperty(name, v) Then Return fallback
        Return v.GetString()
    End Function

    Private Function Bool(e As JsonElement, name As String, fallback As Boolean) As Boolean
        Dim v As JsonElement
        If Not e.TryGetProperty(name, v) Then Return fallback
        Return v.GetBoolean()
    End Function
End Module
