Option Strict On

''' <summary>
''' The protractor's reading on a ramp or a polygon's face under the cursor: its angle to the
''' horizontal, drawn as an arc at its lower end.
''' </summary>
Public NotInheritable Class ProtractorReading
    ''' <summary>The face's lower end, m: where the arc is drawn.</summary>
    Public ReadOnly Property Lower As Vector
    ''' <summary>The face's upper end, m.</summary>
    Public ReadOnly Property Upper As Vector
    ''' <summary>Its angle to the horizontal, 0° to 90°.</summary>
    Public ReadOnly Property Degrees As Double

    ''' <summary>The reading of the face from <paramref name="a"/> to <paramref name="b"/>, m.</summary>
    Public Sub New(a As Vector, b As Vector)
        ' The lower end holds the arc; on a level face, the left one.
        Dim aFirst = a.Y < b.Y OrElse (a.Y = b.Y AndAlso a.X <= b.X)
        _Lower = If(aFirst, a, b)
        _Upper = If(aFirst, b, a)
        _Degrees = TapeMeasure.AngleToHorizontal(a, b)
    End Sub

    ''' <summary>"30.0°".</summary>
    Public ReadOnly Property Label As String
        Get
            Return Units.Num(Degrees, 1) & "°"
        End Get
    End Property

    ''' <summary>Whether the face rises to the right from its lower end (the arc opens that way).</summary>
    Public ReadOnly Property RisesRight As Boolean
        Get
            Return Upper.X >= Lower.X
        End Get
    End Property

    ''' <summary>
    ''' The reading of the ramp (a segment) or polygon face within <paramref name="reach"/> (m) of
    ''' <paramref name="p"/>, the nearest; Nothing when there is none.
    ''' </summary>
    Public Shared Function Near(w As World, p As Vector, reach As Double) As ProtractorReading
        Dim best As ProtractorReading = Nothing
        Dim bestDistance = reach
        For Each b In w.Bodies
            If b.Kind <> ShapeKind.Segment AndAlso b.Kind <> ShapeKind.Polygon Then Continue For
            Dim faces As New List(Of (A As Vector, B As Vector))
            If b.Kind = ShapeKind.Segment Then
                Dim s = DirectCast(b, Segment)
                faces.Add((s.StartPoint, s.EndPoint))
            ElseIf b.Kind = ShapeKind.Polygon Then
                Dim corners = DirectCast(b, Polygon).Vertices
                For i = 0 To corners.Count - 1
                    faces.Add((corners(i), corners((i + 1) Mod corners.Count)))
                Next
            End If
            For Each f In faces
                Dim d = Vector.DistanceToSegment(p, f.A, f.B)
                If d <= bestDistance Then
                    bestDistance = d
                    best = New ProtractorReading(f.A, f.B)
                End If
            Next
        Next
        Return best
    End Function
End Class
