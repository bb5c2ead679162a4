Option Strict On
Imports System.IO
Imports System.Runtime.Serialization.Json
Imports System.Text
Imports System.Xml.Linq

Namespace Scenes
    ''' <summary>
    ''' Writes a world as a physics-scene/1 document: every field explicit (ids, world settings),
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
            Dim bodies As New XElement("bodies", New XAttribute("type", "array"))
            For Each b In world.Bodies
                bodies.Add(BodyElement(b))
            Next
            Dim root = JsonObject("root", JsonValue("format", SceneReader.FormatName), settings, bodies)
            Return ToJson(root)
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
