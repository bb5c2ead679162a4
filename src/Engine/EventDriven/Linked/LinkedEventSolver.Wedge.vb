Option Strict On

' Bodies wedged among contacts (docs/links.md, "Links in the event solver"). Pairwise blows, each with the
' links of its two bodies, can pass a blow back and forth at one instant for ever: a ball caged with no room
' between the two ends of a rod is hit by one end, hits the other, is hit back, and so on, with e = 1 not
' even losing speed. After many events at one instant the contact is resolved instead with every contact
' touching the bodies it moves, all in one blow (LinkedImpulse.ResolveWedged): the same complementarity
' solve, for impulses. With e = 0 every blow is resolved so from the first: with nothing given back, passing it
' pair by pair only creeps towards what the one solve reaches at once, no touching contact approaching (a
' ball wedged between two bodies of a cluster and a third ball was struck up to 70 times at one instant, its
' approach shrinking geometrically).
Partial Friend NotInheritable Class LinkedEventSolver
    ' Blows a body takes within a nanosecond after which a contact of it is resolved with every contact around it
    ' at once. A cradle's cascade hits each ball once or twice; a body wedged is hit again and again.
    Private Const WedgedAfter As Integer = 16

    ' Blows each body has taken at the instant under way.
    Private _hitsNow As Integer() = Array.Empty(Of Integer)()

    ''' <summary>Counts a blow on body i (and j, if ≥ 0) at the instant under way; whether either is now wedged.</summary>
    Private Function Wedged(i As Integer, j As Integer) As Boolean
        _hitsNow(i) += 1
        If j >= 0 Then _hitsNow(j) += 1
        Return _hitsNow(i) > WedgedAfter OrElse (j >= 0 AndAlso _hitsNow(j) > WedgedAfter)
    End Function
    ' At most this many bodies are gathered into one blow.
    Private Const MaxWedgedBodies As Integer = 64

    ''' <summary>
    ''' Adds to the blow under way (the contact of body i with body j, wall <paramref name="side"/> or fixed
    ''' body f at <paramref name="t"/>) every other contact that touches a body of the groups it moves, and in
    ''' turn of the groups those touch, with the links and lasting contacts those groups hold. The bodies are
    ''' written to their states at t before they join. Returns the groups gathered (those given among them).
    ''' </summary>
    Private Function AddTouchingContacts(i As Integer, j As Integer, side As WallSide, f As Integer, t As Double,
                                         groups As List(Of Integer)) As List(Of Integer)
        groups = New List(Of Integer)(groups)
        Dim gathered = groups.Sum(Function(g) _groups(g).Bodies.Count)
        Dim pairs As New HashSet(Of Long)
        If j >= 0 Then pairs.Add(PairKey(i, j))
        Dim own = If(j >= 0, ContactKey.PairValue(i, j), If(f >= 0, ContactKey.FixedValue(i, f), ContactKey.WallValue(i, side)))
        Dim head = 0
        Do While head < groups.Count
            Dim g = groups(head)
            head += 1
            AddStringsAtLength(g)
            AddWatchedRows(g, own)
            For Each c In _groups(g).Bodies
                Dim k = Array.IndexOf(_bodies, c)
                For m = 0 To _bodies.Length - 1
                    If m = k OrElse Not pairs.Add(PairKey(k, m)) OrElse _neverMeet.Contains(PairKey(k, m)) Then Continue For
                    Dim lo = Math.Min(k, m), hi = Math.Max(k, m)
                    If IsHeld(ContactKey.PairValue(lo, hi)) Then Continue For
                    Dim gm = _groupOf(m)
                    If Not groups.Contains(gm) Then
                        If Not MayTouch(k, m) Then Continue For
                        Sync(gm, t)
                    End If
                    Dim normal As Vector
                    If Not Touches(PairGap(lo, hi), t, normal) Then Continue For
                    If Not groups.Contains(gm) Then
                        If gathered + _groups(gm).Bodies.Count > MaxWedgedBodies Then Continue For
                        gathered += _groups(gm).Bodies.Count
                        groups.Add(gm)
                        AddHeldRows(gm)
                    End If
                    _impulse.AddContact(_bodies(lo), _bodies(hi), normal, _world.Restitution)
                Next
                If _world.Walls Then
                    For s = 1 To 4
                        If (k = i AndAlso j < 0 AndAlso f < 0 AndAlso s = side) OrElse IsHeld(ContactKey.WallValue(k, CType(s, WallSide))) Then Continue For
                        AddTouching(k, WallGap(k, CType(s, WallSide)), t)
                    Next
                End If
                For o = 0 To _fixed.Length - 1
                    If (k = i AndAlso o = f) OrElse IsHeld(ContactKey.FixedValue(k, o)) Then Continue For
                    AddTouching(k, FixedGap(k, o), t)
                Next
            Next
        Loop
        Return groups
    End Function

    ''' <summary>
    ''' Group g's contacts that touch without pressing (its motion watches them, so the search below passes them by),
    ''' but the blow's own (<paramref name="own"/>, a key's value): they may part, never press in. Left out, a blow
    ''' that drives one of them in is struck again at once, and passes back and forth between two of the group's
    ''' bodies and a third for ever, the wedge rule finding nothing more to add.
    ''' </summary>
    Private Sub AddWatchedRows(g As Integer, own As Long)
        Dim m = _groups(g).Motion
        For Each c In m.WatchedContacts
            If DirectCast(c.Tag, ContactKey).Value <> own Then _impulse.AddHeld(m.Bodies, c)
        Next
    End Sub

    ''' <summary>
    ''' Group g's strings that its motion holds slack but that are at their full length (within the slop): a string
    ''' that snaps taut at this instant is part of the same blow, or the blow and the snap pass the body back and
    ''' forth between them for ever (a bob on a string struck against another body at its string's length).
    ''' The group's bodies are written to their states now.
    ''' </summary>
    Private Sub AddStringsAtLength(g As Integer)
        Dim held = _groups(g).Motion.HeldLinks
        For Each l In _groups(g).Links
            If l.Kind = LinkKind.String AndAlso Array.IndexOf(held, l) < 0 AndAlso l.Distance >= l.Length - Slop Then _impulse.AddStringAtLength(l)
        Next
    End Sub

    ''' <summary>Body k's contact with a wall or fixed body, if it touches at <paramref name="t"/>.</summary>
    Private Sub AddTouching(k As Integer, gap As LinkedGap, t As Double)
        Dim normal As Vector
        If Touches(gap, t, normal) Then _impulse.AddContact(_bodies(k), Nothing, normal, _world.Restitution)
    End Sub

    ''' <summary>Whether the gap is within the slop at <paramref name="t"/>, and then the contact's <paramref name="normal"/>.</summary>
    Private Shared Function Touches(gap As LinkedGap, t As Double, ByRef normal As Vector) As Boolean
        Dim rate As Double
        If gap.GapAndNormal(t, normal, rate) > Slop Then Return False
        If gap.Difference IsNot Nothing Then normal = gap.ContactNormal(t)
        Return True
    End Function
End Class
