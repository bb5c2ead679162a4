Option Strict On

Namespace Generation
    ''' <summary>The kinds as the command line spells them: "circle,rectangle", "all".</summary>
    Friend Module BodyKindNames
        Private ReadOnly Names As New Dictionary(Of String, BodyKinds)(StringComparer.Ordinal) From {
            {"circle", BodyKinds.Circle}, {"rectangle", BodyKinds.Rectangle}, {"segment", BodyKinds.Segment},
            {"polygon", BodyKinds.Polygon}, {"box", BodyKinds.Box}, {"link", BodyKinds.Link},
            {"default", BodyKinds.Default}, {"all", BodyKinds.All}}

        ''' <summary>Reads a comma-separated list; throws ArgumentException naming an unknown kind.</summary>
        Friend Function Parse(text As String) As BodyKinds
            If text Is Nothing Then Throw New ArgumentNullException(NameOf(text))
            Dim kinds = BodyKinds.None
            For Each part In text.Split(","c)
                Dim name = part.Trim()
                Dim kind As BodyKinds
                If Not Names.TryGetValue(name, kind) Then Throw New ArgumentException("unknown kind '" & name & "' (expected " & String.Join(", ", Names.Keys) & ")", NameOf(text))
                kinds = kinds Or kind
            Next
            Return kinds
        End Function

        ''' <summary>The list <see cref="Parse"/> reads back.</summary>
        Friend Function Format(kinds As BodyKinds) As String
            If kinds = BodyKinds.All Then Return "all"
            Return String.Join(",", Names.Where(Function(n) n.Value <> BodyKinds.Default AndAlso n.Value <> BodyKinds.All AndAlso (kinds And n.Value) = n.Value).Select(Function(n) n.Key))
        End Function
    End Module
End Namespace
