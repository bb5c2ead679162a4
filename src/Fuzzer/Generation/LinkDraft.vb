Option Strict On

Namespace Generation
    ''' <summary>One entry of a scene's "links": a spring, rod or string between two bodies or a body and a fixed point.</summary>
    Friend NotInheritable Class LinkDraft
        ''' <summary>"spring", "rod" or "string".</summary>
        Friend Property Type As String
        Friend Property Id As String
        ''' <summary>The movable body's id.</summary>
        Friend Property A As String
        ''' <summary>The other body's id, or Nothing when the link ends at <see cref="At"/>.</summary>
        Friend Property B As String
        ''' <summary>The fixed point, m, when <see cref="B"/> is Nothing.</summary>
        Friend Property At As Vector
        ''' <summary>Spring constant, N/m (springs).</summary>
        Friend Property Stiffness As Double
        ''' <summary>m, or Nothing for "the distance in the file" (springs).</summary>
        Friend Property RestLength As Double?
        ''' <summary>N·s/m, or Nothing for none (springs).</summary>
        Friend Property Damping As Double?
        ''' <summary>m, or Nothing for "the distance in the file" (rods and strings).</summary>
        Friend Property Length As Double?

        ''' <summary>The link as one physics-scene/1 object.</summary>
        Friend Function ToJson() As String
            Dim j = New JsonText().Add("id", Id).Add("type", Type).Add("a", A)
            If B IsNot Nothing Then j.Add("b", B) Else j.Raw("at", JsonText.Point(At))
            If Type = "spring" Then
                j.Add("stiffness", Stiffness)
                If RestLength.HasValue Then j.Add("rest_length", RestLength.Value)
                If Damping.HasValue Then j.Add("damping", Damping.Value)
            ElseIf Length.HasValue Then
                j.Add("length", Length.Value)
            End If
            Return j.ToString()
        End Function
    End Class
End Namespace
