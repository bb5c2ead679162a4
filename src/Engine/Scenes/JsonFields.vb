Option Strict On
Imports System.Xml.Linq

Namespace Scenes
    ''' <summary>
    ''' Reads typed fields of one JSON object (as the BCL's JSON reader gives it: an element whose
    ''' "type" attribute says number, string, boolean, array, object or null) and names the place of
    ''' every problem, such as "bodies[3].radius".
    ''' </summary>
    Friend NotInheritable Class JsonFields
        Private ReadOnly _element As XElement
        Private ReadOnly _place As String

        ''' <param name="element">an element of JSON type object</param>
        ''' <param name="place">its path: "" for the document, "world", "bodies[3]"</param>
        Friend Sub New(element As XElement, place As String)
            _element = element
            _place = place
        End Sub

        ''' <summary>The path of a field of this object.</summary>
        Friend Function PlaceOf(name As String) As String
            Return If(_place.Length = 0, name, _place & "." & name)
        End Function

        ''' <summary>The field's value, or Nothing when it is absent. A field given twice is an error: which one was meant?</summary>
        Friend Function Find(name As String) As XElement
            Dim found As XElement = Nothing
            For Each e In _element.Elements(name)
                If found IsNot Nothing Then Throw New SceneFormatException(PlaceOf(name), "appears more than once")
                found = e
            Next
            Return found
        End Function

        ''' <summary>The field's value; an error when it is absent.</summary>
        Friend Function Require(name As String) As XElement
            Dim e = Find(name)
            If e Is Nothing Then Throw New SceneFormatException(PlaceOf(name), "is required")
            Return e
        End Function

        Friend Function RequiredNumber(name As String) As Double
            Return AsNumber(Require(name), PlaceOf(name))
        End Function

        Friend Function OptionalNumber(name As String, fallback As Double) As Double
            Dim e = Find(name)
            Return If(e Is Nothing, fallback, AsNumber(e, PlaceOf(name)))
        End Function

        Friend Function RequiredString(name As String) As String
            Return AsString(Require(name), PlaceOf(name))
        End Function

        ''' <summary>The string, or Nothing when the field is absent.</summary>
        Friend Function OptionalString(name As String) As String
            Dim e = Find(name)
            Return If(e Is Nothing, Nothing, AsString(e, PlaceOf(name)))
        End Function

        Friend Function OptionalBoolean(name As String, fallback As Boolean) As Boolean
            Dim e = Find(name)
            If e Is Nothing Then Return fallback
            If JsonType(e) <> "boolean" Then Throw WrongType(e, PlaceOf(name), "true or false")
            Return e.Value = "true"
        End Function

        ''' <summary>The JSON type of a value: number, string, boolean, array, object or null.</summary>
        Friend Shared Function JsonType(e As XElement) As String
            Dim a = e.Attribute("type")
            Return If(a Is Nothing, "string", a.Value)
        End Function

        ''' <summary>"must be &lt;expected&gt;, not &lt;what it is&gt;".</summary>
        Friend Shared Function WrongType(e As XElement, place As String, expected As String) As SceneFormatException
            Dim actual As String
            Select Case JsonType(e)
                Case "number" : actual = "a number"
                Case "boolean" : actual = e.Value
                Case "array" : actual = "an array"
                Case "object" : actual = "an object"
                Case "null" : actual = "null"
                Case Else : actual = "a string"
            End Select
            Return New SceneFormatException(place, "must be " & expected & ", not " & actual)
        End Function

        ''' <summary>A JSON number that must be finite, at <paramref name="place"/> (an array element, say).</summary>
        Friend Shared Function Number(e As XElement, place As String) As Double
            Return AsNumber(e, place)
        End Function

        Private Shared Function AsNumber(e As XElement, place As String) As Double
            If JsonType(e) <> "number" Then Throw WrongType(e, place, "a number")
            Dim problem As String = Nothing
            Dim value = JsonNumber.TryParse(e.Value, problem)
            If Not value.HasValue Then Throw New SceneFormatException(place, problem)
            Return value.Value
        End Function

        Private Shared Function AsString(e As XElement, place As String) As String
            If JsonType(e) <> "string" Then Throw WrongType(e, place, "a string")
            Return e.Value
        End Function
    End Class
End Namespace
