Option Strict On

''' <summary>
''' The answers the scenes are measured against, derived by hand (A-level mechanics). Pure functions.
''' </summary>
Friend Module ClosedForms
    ''' <summary>
    ''' Height of the n-th apex after the drop, m: each bounce multiplies the speed by e and the height
    ''' by e², so apex n = e^(2n) h0.
    ''' </summary>
    Public Function BounceApex(dropHeight As Double, restitution As Double, n As Integer) As Double
        Return Math.Pow(restitution, 2 * n) * dropHeight
    End Function

    ''' <summary>
    ''' Time for a dropped ball to come to rest, s: t0 + 2 t0 (e + e² + …) = t0 (1 + e) / (1 − e),
    ''' with t0 = √(2 h0 / g) the first fall. Infinite for e = 1.
    ''' </summary>
    Public Function BounceRestTime(dropHeight As Double, restitution As Double, gravity As Double) As Double
        If restitution >= 1 Then Return Double.PositiveInfinity
        Dim t0 = Math.Sqrt(2 * dropHeight / gravity)
        Return t0 * (1 + restitution) / (1 - restitution)
    End Function

    ''' <summary>
    ''' Time of the n-th floor impact (n ≥ 1), s: t0 + 2 t0 (e + … + e^(n−1)).
    ''' </summary>
    Public Function BounceImpactTime(dropHeight As Double, restitution As Double, gravity As Double, n As Integer) As Double
        Dim t0 = Math.Sqrt(2 * dropHeight / gravity)
        Dim t = t0
        For k = 1 To n - 1
            t += 2 * t0 * Math.Pow(restitution, k)
        Next
        Return t
    End Function

    ''' <summary>Flight time of a projectile launched from and landing on the same level, s: 2 v0 sin θ / g.</summary>
    Public Function ProjectileFlightTime(speed As Double, angle As Double, gravity As Double) As Double
        Return 2 * speed * Math.Sin(angle) / gravity
    End Function

    ''' <summary>Position at time t of a projectile from p0 with velocity u (suvat: s = ut + ½at²), m.</summary>
    Public Function ProjectilePosition(p0 As Vector, velocity As Vector, gravity As Double, time As Double) As Vector
        Return New Vector(p0.X + velocity.X * time, p0.Y + velocity.Y * time - 0.5 * gravity * time * time)
    End Function

    ''' <summary>
    ''' Exit velocities of an elastic (e = 1) oblique hit between equal masses: striker moving along +x
    ''' at v0, target at rest, impact parameter b (target centre below the striker's line by b), radii r.
    ''' At impact the line of centres makes φ with +x, sin φ = b / (2r): the target leaves along it at
    ''' v0 cos φ, the striker at right angles to it with v0 sin φ.
    ''' </summary>
    Public Function ObliqueExitVelocities(speed As Double, impactParameter As Double, radius As Double) As (Striker As Vector, Target As Vector)
        Dim sinPhi = impactParameter / (2 * radius)
        Dim cosPhi = Math.Sqrt(1 - sinPhi * sinPhi)
        ' Line of centres from striker to target at impact: (cos φ, −sin φ).
        Dim target = New Vector(cosPhi, -sinPhi) * (speed * cosPhi)
        Dim striker = New Vector(speed, 0) - target
        Return (striker, target)
    End Function

    ''' <summary>
    ''' Period of a pendulum of length L released from rest at θ0 (rad), s: T = 4 √(L/g) K(k) with
    ''' k = sin(θ0/2) and K the complete elliptic integral of the first kind, K(k) = π / (2 AGM(1, √(1 − k²)))
    ''' (Gauss's arithmetic–geometric mean). For small θ0 it tends to 2π √(L/g).
    ''' </summary>
    Public Function PendulumPeriod(length As Double, angle As Double, gravity As Double) As Double
        Dim k = Math.Sin(angle / 2)
        Dim a = 1.0, b = Math.Sqrt(1 - k * k)
        For i = 1 To 40
            Dim mean = (a + b) / 2
            b = Math.Sqrt(a * b)
            a = mean
            If Math.Abs(a - b) <= 1.0E-16 * a Then Exit For
        Next
        Return 4 * Math.Sqrt(length / gravity) * Math.PI / (2 * a)
    End Function

    ''' <summary>
    ''' Height of a mass on an undamped vertical spring released at rest with the spring unstretched,
    ''' m: it oscillates about y_eq = y0 − mg/k with amplitude mg/k and ω = √(k/m), so
    ''' y(t) = y0 − (mg/k)(1 − cos ωt).
    ''' </summary>
    Public Function SpringHeight(y0 As Double, stiffness As Double, mass As Double, gravity As Double, time As Double) As Double
        Dim stretch = mass * gravity / stiffness
        Return y0 - stretch * (1 - Math.Cos(Math.Sqrt(stiffness / mass) * time))
    End Function
End Module
