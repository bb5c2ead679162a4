Option Strict On

''' <summary>
''' Two rods or taut strings from fixed points to one body that lie in line (docs/links.md, "Two ties in line"). Each
''' holds the body on (a rod) or inside (a string) a circle round its anchor, and in line the two circles touch at
''' the body. Their rows are then one row twice: to first order the body may move across them, along the tangent t.
''' To second order it may not, unless the circles' shapes agree there. With s the distance moved along t and z the
''' distance moved towards anchor 1 (unit u from the body to it), distance to an anchor at L along u is about
''' L − z + s²/(2L), and to one at L' along σu (σ = ±1) about L' − σz + s²/(2L'). So
''' <list type="bullet">
''' <item>a rod of length L asks z = s²/(2L); a string asks z ≥ s²/(2L) (it may shorten, never stretch);</item>
''' <item>anchors on opposite sides (σ = −1): the second asks −z = s²/(2L') (rod) or −z ≥ s²/(2L') (string), which no
''' z meets with the first unless s = 0: the body is held where it is, whatever the two are;</item>
''' <item>anchors on the same side (σ = +1): two strings always leave room (z as large as needed: it swings on the
''' shorter); a rod and a string leave it free only if the rod is the shorter of the two (it swings on the rod,
''' and the longer string goes slack); two rods only if their lengths are equal, that is the same anchor.</item>
''' </list>
''' Where the body is held, it cannot move along t at all: the pair adds a row along t at the body, kept at its
''' value now (a <see cref="Constraint.Lock"/>), which the rows along u, only one of them independent, cannot give.
''' </summary>
Friend Module TieLock
    ''' <summary>Rows whose directions differ by less than this sine are in line (the margin rows count as depending within: 10⁻⁴ rad).</summary>
    Private Const InLineSine As Double = 0.0001

    ''' <summary>
    ''' The lock rows for <paramref name="rows"/> at <paramref name="state"/> (per body x, y, vx, vy): one along the
    ''' tangent for each body held by two of its anchored ties in line (rods, and strings taken as taut), at most
    ''' one per body.
    ''' </summary>
    Friend Function Find(rows As IEnumerable(Of Constraint), state As Double()) As List(Of Constraint)
        Dim locks As New List(Of Constraint)
        Dim ties = rows.Where(Function(c) c.Shape = ConstraintShape.Tie AndAlso c.B < 0).ToList()
        Dim locked As New HashSet(Of Integer)
        For p = 0 To ties.Count - 1
            For q = p + 1 To ties.Count - 1
                Dim first = ties(p), second = ties(q)
                If first.A <> second.A OrElse locked.Contains(first.A) Then Continue For
                Dim u1 As Vector, u2 As Vector, value As Double, rate As Double, curvature As Double
                first.Measure(state, u1, value, rate, curvature)
                second.Measure(state, u2, value, rate, curvature)
                If Math.Abs(Vector.Cross(u1, u2)) > InLineSine Then Continue For
                If Not Holds(first.Holds, first.Length, second.Holds, second.Length, Vector.Dot(u1, u2) > 0) Then Continue For
                Dim t = New Vector(-u1.Y, u1.X)
                Dim body = New Vector(state(4 * first.A), state(4 * first.A + 1))
                locks.Add(Constraint.Lock(first.A, t, Vector.Dot(t, body), Math.Min(first.Length, second.Length), first.Tag))
                locked.Add(first.A)
            Next
        Next
        Return locks
    End Function

    ''' <summary>
    ''' The contacts of <paramref name="rows"/> with walls and fixed bodies that a tie of the same body to a fixed point
    ''' (a rod, or a string taken as taut) already keeps, at <paramref name="state"/>: the contact lies in line with the
    ''' tie and opens the way the tie pulls (a ball on the floor straight under the point its string is tied to, the
    ''' string as long as the height). With z the move towards the anchor and s along the tangent, the tie asks
    ''' z ≥ s²/(2L) (z = s²/(2L) for a rod) and the contact z ≥ 0, or z ≥ −s²/(2R) round a convex body: the tie's ask
    ''' is the stronger, so the contact never pushes. Taken as a row of its own beside the tie, a few nanometres off the
    ''' line (the two then all but parallel), it made a corner of the two: a ball swinging through the bottom of its
    ''' swing, grazing the floor, was stopped dead there.
    ''' </summary>
    Friend Function ImpliedContacts(rows As IEnumerable(Of Constraint), state As Double()) As HashSet(Of Constraint)
        Dim implied As New HashSet(Of Constraint)
        Dim ties = rows.Where(Function(c) c.Shape = ConstraintShape.Tie AndAlso c.B < 0).ToList()
        If ties.Count = 0 Then Return implied
        For Each c In rows
            If c.Shape = ConstraintShape.Tie OrElse c.IsLock OrElse c.B >= 0 Then Continue For
            Dim uc As Vector, value As Double, rate As Double, curvature As Double
            c.Measure(state, uc, value, rate, curvature)
            For Each t In ties
                If t.A <> c.A Then Continue For
                Dim ut As Vector
                t.Measure(state, ut, value, rate, curvature)
                If KeepsOpen(ut, uc) Then
                    implied.Add(c)
                    Exit For
                End If
            Next
        Next
        Return implied
    End Function

    ''' <summary>
    ''' Whether a tie pulling its body along <paramref name="towardsAnchor"/> (unit) keeps a contact that opens as the body
    ''' moves along <paramref name="opening"/> (unit) from ever pushing: the two in line, the same way (see
    ''' <see cref="ImpliedContacts"/>).
    ''' </summary>
    Friend Function KeepsOpen(towardsAnchor As Vector, opening As Vector) As Boolean
        Return Vector.Dot(towardsAnchor, opening) > 0 AndAlso Math.Abs(Vector.Cross(towardsAnchor, opening)) <= InLineSine
    End Function

    ''' <summary>
    ''' Whether two ties in line hold their body where it is: <paramref name="rod1"/> and <paramref name="rod2"/> say
    ''' whether each is a rod (else a string), L1 and L2 their lengths (m), <paramref name="sameSide"/> whether the
    ''' anchors lie on the same side of the body (see the summary above for the reasoning).
    ''' </summary>
    Friend Function Holds(rod1 As Boolean, length1 As Double, rod2 As Boolean, length2 As Double, sameSide As Boolean) As Boolean
        If Not sameSide Then Return True
        If rod1 AndAlso rod2 Then Return length1 <> length2
        If rod1 Then Return length1 > length2
        If rod2 Then Return length2 > length1
        Return False
    End Function
End Module
