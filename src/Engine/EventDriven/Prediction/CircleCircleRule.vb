Option Strict On

''' <summary>
''' Two circles (one may be fixed): K is a point with radius R = r_A + r_B, so they touch when the
''' centres are R apart: a quadratic when both feel the same acceleration, a quartic otherwise
''' (<see cref="TimeOfImpact.CircleCircleAccelerated"/>).
''' The normal is the line between the centres. K has no edges, so the one feature is its corner, 0 + 0.
''' </summary>
Friend NotInheritable Class CircleCircleRule
    Implements IContactRule

    Public Function TimeOfImpact(ByRef q As ContactQuery, ByRef feature As Integer) As Double Implements IContactRule.TimeOfImpact
        feature = 0
        Dim sumR = q.A.Radius + q.B.Radius
        ' Relative to B, A's centre must come within R of B's: not before the horizon, no root finding.
        If (q.Da.X <> 0 OrElse q.Da.Y <> 0) AndAlso
           Not PathBox.MayReach(q.D.X, q.D.Y, q.Dv.X, q.Dv.Y, q.Da.X, q.Da.Y, q.Horizon, 0, 0, 0, 0, sumR + q.Slop) Then Return Double.PositiveInfinity
        Return Global.PhysicsEngine.TimeOfImpact.CircleCircleAccelerated(q.D.X, q.D.Y, q.Dv.X, q.Dv.Y, q.Da.X, q.Da.Y, sumR, q.Slop, q.SpeedScale)
    End Function

    Public Function Normal(ByRef q As ContactQuery, feature As Integer, ByRef correction As Double) As Vector Implements IContactRule.Normal
        correction = 0
        Return q.D.Normalized(New Vector(0, 1))
    End Function
End Class
