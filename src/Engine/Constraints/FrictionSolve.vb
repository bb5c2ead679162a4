Option Strict On

''' <summary>
''' The complementarity solve of <see cref="ContactSolve"/> with Coulomb friction at the rough flat contacts that
''' press (docs/contact.md, "Friction"): one sliding is pushed back along its face by μk times its push, one not
''' sliding is held along its face (a pair of opposite rows, one of which pushes) while that takes at most μs times
''' its push, and slides the way it is pulled when it would take more. The pushes friction depends on are those of
''' the solve before, so it is solved again until they, the contacts that push and the ones that stick, no longer
''' change. Without friction, one solve. Used by the event solver for the accelerations of a group about to move,
''' and by <see cref="BodyForces"/> for the forces it shows.
''' </summary>
Friend Module FrictionSolve
    ''' <summary>
    ''' Solves for the accelerations <paramref name="result"/> (m/s²) of bodies with <paramref name="inverse"/> masses
    ''' (1/kg) and <paramref name="free"/> accelerations, held by <paramref name="rows"/> (their
    ''' <paramref name="solveRows"/> measured at state <paramref name="y"/>), within <paramref name="tolerance"/>
    ''' (m/s²). Writes each row's push to <paramref name="forces"/> (N) and, when <paramref name="friction"/> is not
    ''' Nothing, each row's friction force along its face's direction on body A (N; 0 for a smooth row).
    ''' </summary>
    Friend Sub Solve(solver As ContactSolve, inverse As Double(), free As Vector(), rows As IList(Of Constraint), solveRows As ContactRow(), y As Double(),
                     tolerance As Double, result As Vector(), forces As Double(), friction As Double())
        If friction IsNot Nothing Then Array.Clear(friction, 0, friction.Length)
        solver.Solve(inverse, free, solveRows, tolerance, result, forces)
        Dim rough = Enumerable.Range(0, rows.Count).Where(Function(k) rows(k).Shape = ConstraintShape.Plane AndAlso Not rows(k).Holds AndAlso
                                                            (rows(k).Friction > 0 OrElse rows(k).StaticFriction > 0)).ToList()
        If rough.Count = 0 Then Return
        Dim speed = 0.0
        For k = 0 To inverse.Length - 1
            speed = Math.Max(speed, New Vector(y(4 * k + 2), y(4 * k + 3)).Length)
        Next
        Dim still = 0.000000001 * speed + 0.000000000001
        Dim sliding(rows.Count - 1) As Integer
        For Each k In rough
            Dim rate = rows(k).SlidingRate(y)
            If Math.Abs(rate) > still Then sliding(k) = Math.Sign(rate)
        Next
        Dim pushed(inverse.Length - 1) As Vector
        Dim trial(inverse.Length - 1) As Vector
        Dim along(rows.Count - 1) As Double
        For iteration = 1 To 4 * rough.Count + 8
            Array.Copy(free, pushed, free.Length)
            Array.Clear(along, 0, along.Length)
            Dim all As New List(Of ContactRow)(solveRows)
            Dim stickAt As New Dictionary(Of Integer, Integer)
            For Each k In rough
                If Not (forces(k) > 0) Then Continue For
                Dim c = rows(k)
                If sliding(k) <> 0 Then
                    along(k) = -c.Friction * forces(k) * sliding(k)
                    Dim f = c.Along * along(k)
                    pushed(c.A) += f * inverse(c.A)
                    If c.B >= 0 Then pushed(c.B) -= f * inverse(c.B)
                Else
                    stickAt(k) = all.Count
                    all.Add(New ContactRow(c.A, c.B, c.Along, 0, False))
                    all.Add(New ContactRow(c.A, c.B, -c.Along, 0, False))
                End If
            Next
            Dim trialForces(all.Count - 1) As Double
            solver.Solve(inverse, pushed, all, tolerance, trial, trialForces)
            ' The sticking contact that needs most beyond μs times its push starts to slide.
            Dim worst = -1, excess = 0.0, pull = 0.0
            For Each entry In stickAt
                Dim n = trialForces(entry.Key)
                along(entry.Key) = trialForces(entry.Value) - trialForces(entry.Value + 1)
                Dim over = Math.Abs(along(entry.Key)) - rows(entry.Key).StaticFriction * Math.Max(n, 0)
                If over > excess + 0.000000001 * (Math.Abs(along(entry.Key)) + Math.Abs(n)) Then worst = entry.Key : excess = over : pull = along(entry.Key)
            Next
            Dim settled = worst < 0
            For k = 0 To rows.Count - 1
                If (forces(k) > 0) <> (trialForces(k) > 0) OrElse Math.Abs(forces(k) - trialForces(k)) > 0.000000000001 * (Math.Abs(forces(k)) + Math.Abs(trialForces(k))) Then settled = False
                forces(k) = trialForces(k)
            Next
            Array.Copy(trial, result, trial.Length)
            If friction IsNot Nothing Then Array.Copy(along, friction, rows.Count)
            If worst >= 0 Then sliding(worst) = -Math.Sign(pull)
            If settled Then Exit For
        Next
    End Sub
End Module
