Option Strict On

''' <summary>
''' Contact handling for the stepping solvers, after each sub-step: find overlaps, push the bodies
''' apart (static resolution, shared in proportion to inverse mass) and apply the impulse (dynamic
''' resolution). A contact whose approach speed is below what gravity adds in one step is a resting
''' contact: it is resolved with e = 0 and not reported as a collision, so a ball at rest does not
''' jitter, sink, or flood the log.
''' </summary>
Friend Module StepContacts
    Friend Sub Resolve(world As World, time As Double)
        Dim circles = world.Circles
        Dim dragged = world.DraggedCircle
        Dim e = world.Restitution
        For i = 0 To circles.Count - 1
            Dim a = circles(i)
            If a.IsFixed Then Continue For
            Dim invA = If(a Is dragged, 0.0, a.InverseMass)
            For j = 0 To circles.Count - 1
                If j = i Then Continue For
                Dim b = circles(j)
                If Not b.IsFixed AndAlso j < i Then Continue For ' each movable pair once
                Dim contact = Collider.CircleCircle(a.Position, a.Radius, b.Position, b.Radius)
                If contact.Depth <= 0 Then Continue For
                Dim invB = If(b Is dragged, 0.0, b.InverseMass)
                Dim kind = If(b.IsFixed, CollisionKind.CircleFixed, CollisionKind.CircleCircle)
                Respond(world, time, a, invA, b, invB, contact, e, kind, WallSide.None)
            Next
            For Each r In world.Rectangles
                Dim contact = Collider.CircleRectangle(a.Position, a.Radius, r.Min, r.Max)
                If contact.Depth <= 0 Then Continue For
                Respond(world, time, a, invA, r, 0, contact, e, CollisionKind.CircleRectangle, WallSide.None)
            Next
            If world.Walls Then
                For Each side In {WallSide.Left, WallSide.Right, WallSide.Bottom, WallSide.Top}
                    Dim contact = Collider.CircleWall(a.Position, a.Radius, side, world.Width, world.Height)
                    If contact.Depth <= 0 Then Continue For
                    Respond(world, time, a, invA, Nothing, 0, contact, e, CollisionKind.CircleWall, side)
                Next
            End If
        Next
    End Sub

    Private Sub Respond(world As World, time As Double, a As Circle, invA As Double, b As Shape, invB As Double,
                        contact As Contact, e As Double, kind As CollisionKind, side As WallSide)
        Dim n = contact.Normal
        Dim bc = TryCast(b, Circle)
        ' Static resolution: move apart along n in proportion to inverse mass.
        Dim sumInv = invA + invB
        If sumInv = 0 Then
            If a Is world.DraggedCircle Then Return ' dragged into something fixed: not pushed back
            sumInv = 1 : invA = 1
        End If
        a.Position += n * (contact.Depth * invA / sumInv)
        If bc IsNot Nothing AndAlso Not bc.IsFixed Then bc.Position -= n * (contact.Depth * invB / sumInv)

        ' Dynamic resolution.
        Dim vb = If(bc Is Nothing OrElse bc.IsFixed, Vector.Zero, bc.Velocity)
        Dim approach = -Vector.Dot(a.Velocity - vb, n)
        If approach <= 0 Then Return
        Dim restingSpeed = 2 * world.Gravity * If(world.Solver.TimeStep, 0.0)
        Dim resting = approach <= restingSpeed
        Dim result = Impulse.Resolve(a.Velocity, invA, vb, invB, n, If(resting, 0.0, e))
        Dim aBefore = a.Velocity
        a.Velocity = result.A
        If bc IsNot Nothing AndAlso Not bc.IsFixed Then bc.Velocity = result.B
        If Not resting Then
            world.ReportCollision(New CollisionRecord(time, a, b, side, kind, aBefore, result.A, vb, If(bc Is Nothing OrElse bc.IsFixed, Vector.Zero, result.B)))
        End If
    End Sub
End Module
