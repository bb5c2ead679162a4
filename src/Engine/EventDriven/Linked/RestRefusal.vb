Option Strict On

''' <summary>
''' The sentence with which the linked event solver refuses a body coming to rest where it has no rule to
''' hold it (docs/links.md, section 6): what was coming to rest, on what, and why that is not followed.
''' </summary>
Friend Module RestRefusal
    ''' <summary>
    ''' The message for <paramref name="body"/> (held by <paramref name="links"/>) coming to rest on
    ''' <paramref name="support"/> (Nothing: the floor; held by <paramref name="supportLinks"/> when it moves)
    ''' across a contact with unit <paramref name="normal"/>; with no support, the wall <paramref name="side"/>
    ''' (the floor unless said).
    ''' </summary>
    Friend Function Message(body As Shape, links As IReadOnlyCollection(Of Link), support As Shape, supportLinks As IReadOnlyCollection(Of Link), normal As Vector,
                            Optional side As WallSide = WallSide.Bottom) As String
        Dim what = Name(body) & If(links.Count > 0, " on " & If(links.Count = 1, "a " & KindName(links.First()), "links"), "")
        Dim where = If(support IsNot Nothing, Name(support), WallName(side))
        Return $"the event solver does not yet let {what} come to rest on {where} in a scene with links ({Reason(links, support, supportLinks, normal)}); use --solver verlet"
    End Function

    Private Function Reason(links As IReadOnlyCollection(Of Link), support As Shape, supportLinks As IReadOnlyCollection(Of Link), normal As Vector) As String
        If links.Count > 1 OrElse links.Any(Function(l) l.Kind = LinkKind.Rod) Then Return "a body on a rod or on more than one link does not rest"
        If links.Count = 1 AndAlso Math.Abs(normal.X) > 0 Then Return "a body on a link rests only on a level face"
        If links.Count = 1 AndAlso links.First().Kind = LinkKind.Spring Then Return "a body on a spring rests only still, with the spring straight up and pulling less than its weight"
        If links.Count = 1 Then Return "a body on a string rests only while the string is slack"
        If support IsNot Nothing AndAlso Not support.IsFixed Then
            If supportLinks IsNot Nothing AndAlso supportLinks.Count > 0 Then Return "a body held by links is no support"
            Return "a body rests on another only on a level face of one that rests itself"
        End If
        Return "a body rests only on flat faces, not on a curve or a corner"
    End Function

    Private Function Name(s As Shape) As String
        Dim id = If(String.IsNullOrEmpty(s.Id), "", $" '{s.Id}'")
        Select Case s.Kind
            Case ShapeKind.Circle : Return If(s.IsFixed, "a fixed circle", "a ball") & id
            Case ShapeKind.Rectangle : Return If(s.IsFixed, "a fixed rectangle", "a box") & id
            Case ShapeKind.Segment : Return "a segment" & id
            Case Else : Return If(s.IsFixed, "a fixed polygon", "a polygon") & id
        End Select
    End Function

    Private Function WallName(side As WallSide) As String
        Select Case side
            Case WallSide.Left : Return "the left wall"
            Case WallSide.Right : Return "the right wall"
            Case WallSide.Top : Return "the ceiling"
            Case Else : Return "the floor"
        End Select
    End Function

    Private Function KindName(l As Link) As String
        Select Case l.Kind
            Case LinkKind.Rod : Return "rod"
            Case LinkKind.String : Return "string"
            Case Else : Return "spring"
        End Select
    End Function
End Module
