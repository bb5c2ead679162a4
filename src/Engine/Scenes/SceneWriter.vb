Option Strict On
Imports System.IO
Imports System.Runtime.Serialization.Json
Imports System.Text
Imports System.Xml.Linq

Namespace Scenes
    ''' <summary>
    ''' Writes a world as a physics-scene/1 document: every field explicit (ids, world settings, links),
    ''' numbers in round-trip precision, so that reading it back gives exactly the same scene.
    ''' </summary>
    Friend Module SceneWriter
        Friend Function Write(world As World) As String
            If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
            Dim settings = JsonObject("world",
                JsonValue("width", world.Width),
                JsonValue("height", world.Height),
                JsonValue("gravity", world.Gravity),
                JsonValue("restitution", world.Restitution),
                JsonValue("walls", world.Walls))
            ' Friction and air only when set, so a scene without them is written as before.
            If world.Friction <> 0 Then settings.Add(JsonValue("friction", world.Friction))
            If world.StaticFriction.HasValue Then settings.Add(JsonValue("static_friction", world.StaticFriction.Value))
            If world.AirDensity <> 0 Then settings.Add(JsonValue("air_density", world.AirDensity))
            Dim bodies As New XElement("bodies", New XAttribute("type", "array"))
            For Each b In world.Bodies
                bodies.Add(BodyElement(b))
            Next
            ' Liquids are entries of "bodies" too (they share its ids), after the bodies.
            For Each l In world.Liquids
                bodies.Add(LiquidElement(l))
            Next
            Dim root = JsonObject("root", JsonValue("format", SceneReader.FormatName), settings, bodies)
            ' A scene without links is written as before, so older builds read it unchanged.
            If world.Links.Count > 0 Then
                Dim links As New XElement("links", New XAttribute("type", "array"))
                For Each l In world.Links
                    links.Add(LinkElement(l))
                Next
                root.Add(links)
            End If
            Return ToJson(root)
        End Function

        ''' <summary>
        ''' Every field explicit. A rod's or string's length is always written: its default, the distance in
        ''' the file, follows the bodies, which have moved by the time a running scene is saved.
        ''' </summary>
        Private Function LinkElement(l As Link) As XElement
            Dim e = JsonObject("item", JsonValue("id", l.Id), JsonValue("type", l.KindName), JsonValue("a", l.A.Id))
            If l.B Is Nothing Then
                e.Add(New XElement("at", New XAttribute("type", "array"),
                                   New XElement("item", New XAttribute("type", "number"), JsonNumber.Format(l.Anchor.X)),
                                   New XElement("item", New XAttribute("type", "number"), JsonNumber.Format(l.Anchor.Y))))
            Else
                e.Add(JsonValue("b", l.B.Id))
            End If
            If l.Kind = LinkKind.Spring Then
                e.Add(JsonValue("stiffness", l.Stiffness), JsonValue("rest_length", l.Length), JsonValue("damping", l.Damping))
            Else
                e.Add(JsonValue("length", l.Length))
            End If
            Return e
        End Function

        Private Function BodyElement(b As Shape) As XElement
            Dim e = JsonObject("item", JsonValue("id", b.Id))
            Select Case b.Kind
                Case ShapeKind.Circle
                    Dim c = DirectCast(b, Circle)
                    e.Add(JsonValue("type", "circle"), JsonValue("x", c.Position.X), JsonValue("y", c.Position.Y), JsonValue("radius", c.Radius))
                Case ShapeKind.Rectangle
                    Dim r = DirectCast(b, Rectangle)
                    e.Add(JsonValue("type", "rectangle"), JsonValue("x", r.Position.X), JsonValue("y", r.Position.Y), JsonValue("width", r.Width), JsonValue("height", r.Height))
                Case ShapeKind.Segment
                    Dim sg = DirectCast(b, Segment)
                    e.Add(JsonValue("type", "segment"), JsonValue("x1", sg.StartPoint.X), JsonValue("y1", sg.StartPoint.Y),
                          JsonValue("x2", sg.EndPoint.X), JsonValue("y2", sg.EndPoint.Y))
                Case Else
                    Dim corners As New XElement("vertices", New XAttribute("type", "array"))
                    For Each v In DirectCast(b, Polygon).Vertices
                        corners.Add(New XElement("item", New XAttribute("type", "array"),
                                                 New XElement("item", New XAttribute("type", "number"), JsonNumber.Format(v.X)),
                                                 New XElement("item", New XAttribute("type", "number"), JsonNumber.Format(v.Y))))
                    Next
                    e.Add(JsonValue("type", "polygon"), corners)
            End Select
            ' Every kind says whether it is fixed where that is not its default, and a movable body its mass and velocity.
            If b.IsFixed Then
                If b.Kind = ShapeKind.Circle OrElse b.Kind = ShapeKind.Polygon Then e.Add(JsonValue("fixed", True))
            Else
                If b.Kind = ShapeKind.Rectangle Then e.Add(JsonValue("fixed", False))
                e.Add(JsonValue("mass", b.Mass), JsonValue("vx", b.Velocity.X), JsonValue("vy", b.Velocity.Y))
            End If
            If b.Color IsNot Nothing Then e.Add(JsonValue("color", b.Color))
            ' A body's own friction and drag only when it has them.
            If b.Friction.HasValue Then e.Add(JsonValue("friction", b.Friction.Value))
            If b.StaticFriction.HasValue Then e.Add(JsonValue("static_friction", b.StaticFriction.Value))
            If Not b.IsFixed Then
                If b.DragCoefficient <> 0 Then e.Add(JsonValue("drag_coefficient", b.DragCoefficient))
                If b.LinearDrag <> 0 Then e.Add(JsonValue("linear_drag", b.LinearDrag))
            End If
            Return e
        End Function

        Private Function LiquidElement(l As Liquid) As XElement
            Dim e = JsonObject("item", JsonValue("id", l.Id), JsonValue("type", "liquid"),
                               JsonValue("x", l.Min.X), JsonValue("y", l.Min.Y), JsonValue("width", l.Width), JsonValue("height", l.Height),
                               JsonValue("density", l.Density))
            If l.DragCoefficient <> 0 Then e.Add(JsonValue("drag_coefficient", l.DragCoefficient))
            If l.LinearDrag <> 0 Then e.Add(JsonValue("linear_drag", l.LinearDrag))
            If l.Color IsNot Nothing Then e.Add(JsonValue("color", l.Color))
            Return e
        End Function

        Private Function JsonObject(name As String, ParamArray members As XElement()) As XElement
            Return New XElement(name, New XAttribute("type", "object"), members)
        End Function

        Private Function JsonValue(name As String, value As Double) As XElement
            Return New XElement(name, New XAttribute("type", "number"), JsonNumber.Format(value))
        End Function

        Private Function JsonValue(name As String, value As String) As XElement
            Return New XElement(name, New XAttribute("type", "string"), value)
        End Function

        Private Function JsonValue(name As String, value As Boolean) As XElement
            Return New XElement(name, New XAttribute("type", "boolean"), If(value, "true", "false"))
        End Function

        Private Function ToJson(root As XElement) As String
            Using stream As New MemoryStream()
                Using writer = JsonReaderWriterFactory.CreateJsonWriter(stream, New UTF8Encoding(False), False, True, "  ")
                    root.WriteTo(writer)
                    writer.Flush()
                End Using
                ' The writer escapes every "/" as "\/"; both are valid JSON, and "physics-scene/1" reads better.
                ' A "/" is never written bare, so each "\/" is exactly one escaped slash.
                Dim text = Encoding.UTF8.GetString(stream.ToArray()).Replace("\/", "/")
                Return text & vbLf
            End Using
        End Function
    End Module
End Namespace
