Option Strict On

Imports System.Globalization

' Rods and taut strings as the hand and the file leave them (docs/links.md, "Holding the links"): a rod keeps its
' length and a string never stretches past its own, so a body carried by hand stays within reach of its anchors,
' and a state whose ends move apart along a rod (a velocity typed or read from a file) is made to keep it, saying so.
Partial Public NotInheritable Class World
    ''' <summary>
    ''' Where the hand may take <paramref name="body"/>'s reference point, m, given <paramref name="target"/>: each rod
    ''' to a fixed point keeps its centre at the rod's length from it, each string no further than its length (a
    ''' spring stretches as the hand likes). Links to movable bodies pull those along instead.
    ''' </summary>
    Public Function WithinLinks(body As Shape, target As Vector) As Vector
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim offset = body.CentreOfMass - body.Position
        Dim centre = target + offset
        For Each l In _links
            If l.Kind = LinkKind.Spring OrElse Not l.IsAnchored OrElse l.A IsNot body Then Continue For
            Dim fromAnchor = centre - l.EndB
            Dim d = fromAnchor.Length
            If d = 0 Then Continue For
            If l.Kind = LinkKind.Rod OrElse d > l.Length Then centre = l.EndB + fromAnchor * (l.Length / d)
        Next
        Return centre - offset
    End Function

    ''' <summary>
    ''' Makes every rod keep its length and every string at its length not stretch: ends off their length are moved
    ''' back onto it, and velocities that move a rod's ends apart or together (or a taut string's apart) are changed by
    ''' the least change of kinetic energy that stops it (the complementarity solve of docs/contact.md). Returns one
    ''' plain line for each link it changed, naming it and the kinetic energy before and after; nothing when every link
    ''' already held. The command line prints these lines when it loads a scene; dropping a carried body applies it.
    ''' </summary>
    Public Function HoldLinks() As IReadOnlyList(Of String)
        Dim notes As New List(Of String)
        Dim ties = _links.Where(Function(l) l.Kind <> LinkKind.Spring).ToList()
        If ties.Count = 0 Then Return notes
        Dim bodies = _movables.ToList()
        Dim index As New Dictionary(Of Shape, Integer)
        For k = 0 To bodies.Count - 1
            index(bodies(k)) = k
        Next
        ' Lengths first: a few passes of moving each offending link's ends along it, in proportion to inverse mass.
        Dim moved As New HashSet(Of Link)
        For pass = 1 To 20
            Dim worst = 0.0
            For Each l In ties
                Dim r = l.EndB - l.EndA
                Dim d = r.Length
                Dim off = d - l.Length
                If l.Kind = LinkKind.String AndAlso off <= 0 Then Continue For
                If Math.Abs(off) <= 0.000000000001 * l.Length OrElse d = 0 Then Continue For
                Dim wa = l.A.InverseMass, wb = If(l.IsAnchored, 0, l.B.InverseMass)
                If wa + wb = 0 Then Continue For
                Dim u = r / d
                l.A.Position += u * (off * wa / (wa + wb))
                If Not l.IsAnchored Then l.B.Position -= u * (off * wb / (wa + wb))
                moved.Add(l)
                worst = Math.Max(worst, Math.Abs(off) / l.Length)
            Next
            If worst <= 0.000000000001 Then Exit For
            ' Two rods to nearly the same direction (two fixed points almost in line with the body): moving the ends along
            ' one link at a time undoes the other's each pass and creeps to their crossing. All at once it is reached.
            If pass = 20 Then PolishLengths(ties, bodies, index)
        Next
        ' Then speeds along them.
        Dim rows As New List(Of ContactRow), rowLinks As New List(Of Link)
        Dim scale = 0.0
        For Each b In bodies
            scale = Math.Max(scale, b.Velocity.Length)
        Next
        For Each l In ties
            If l.Kind = LinkKind.String AndAlso l.Distance < l.Length * (1 - 0.000000001) Then Continue For
            Dim u = (l.EndB - l.EndA).Normalized(Vector.Zero)
            If u = Vector.Zero Then Continue For
            rows.Add(New ContactRow(index(l.A), If(l.IsAnchored, ContactRow.None, index(l.B)), u, 0, l.Kind = LinkKind.Rod))
            rowLinks.Add(l)
        Next
        Dim tolerance = 0.000000001 * scale
        Dim stretching = Enumerable.Range(0, rows.Count).Where(Function(k) Math.Abs(rowLinks(k).StretchRate) > tolerance AndAlso
                                                                   (rows(k).Holds OrElse rowLinks(k).StretchRate > 0)).Select(Function(k) rowLinks(k)).ToList()
        Dim before = bodies.Sum(Function(b) b.KineticEnergy)
        If stretching.Count > 0 Then
            Dim result(bodies.Count - 1) As Vector, forces(rows.Count - 1) As Double
            Call New ContactSolve().Solve(bodies.Select(Function(b) b.InverseMass).ToArray(), bodies.Select(Function(b) b.Velocity).ToArray(), rows,
                                          ContactSolve.ApproachTolerance * scale, result, forces)
            For k = 0 To bodies.Count - 1
                bodies(k).Velocity = result(k)
            Next
        End If
        Dim after = bodies.Sum(Function(b) b.KineticEnergy)
        Dim inv = CultureInfo.InvariantCulture
        For Each l In moved.Union(stretching)
            Dim k = _links.IndexOf(l)
            notes.Add(String.Format(inv, "links[{0}] ('{1}', a {2}): its ends {3}; they now keep its length (kinetic energy {4:G6} J before, {5:G6} J after)",
                                    k, l.Id, l.KindName,
                                    If(moved.Contains(l), "were off its length", "moved apart along it"), before, after))
        Next
        If notes.Count > 0 Then _solver?.Invalidate(Nothing)
        Return notes
    End Function

    ''' <summary>
    ''' Puts every rod, and every string at or past its length, at its length at once: the least mass-weighted move of
    ''' the bodies (Gauss–Newton steps, <see cref="ConstraintSet.ProjectPositions"/>). Left as it is where the links
    ''' depend on one another (two rods in line): the passes before have done what can be done. <paramref name="index"/>:
    ''' each movable body's place in <paramref name="bodies"/>.
    ''' </summary>
    Private Shared Sub PolishLengths(ties As List(Of Link), bodies As List(Of Shape), index As Dictionary(Of Shape, Integer))
        Dim held = ties.Where(Function(l) index.ContainsKey(l.A) AndAlso (l.IsAnchored OrElse index.ContainsKey(l.B)) AndAlso
                                          (l.Kind = LinkKind.Rod OrElse l.Distance >= l.Length)).ToList()
        If held.Count = 0 Then Return
        Dim rows = held.Select(Function(l) Constraint.Tie(index(l.A), If(l.IsAnchored, -1, index(l.B)), If(l.IsAnchored, l.EndB, Vector.Zero),
                                                          l.Length, l.Kind = LinkKind.Rod)).ToArray()
        Dim y = Constraint.StateOf(bodies)
        Try
            Call New ConstraintSet(rows, bodies.Select(Function(b) b.InverseMass).ToArray()).ProjectPositions(y)
        Catch ex As InvalidOperationException
            Return
        End Try
        For k = 0 To bodies.Count - 1
            bodies(k).Position += New Vector(y(4 * k), y(4 * k + 1)) - bodies(k).CentreOfMass
        Next
    End Sub
End Class
