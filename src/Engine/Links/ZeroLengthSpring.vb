Option Strict On

''' <summary>
''' A body on a spring of rest length 0 to a fixed anchor, under gravity, in closed form. The spring
''' pulls with −k (x − anchor) and gravity adds m g, so relative to the equilibrium
''' x_eq = anchor − (0, mg/k) the motion is m e'' = −k e − c e': a damped harmonic oscillator in each
''' direction separately (<see cref="DampedOscillator"/>), an ellipse that shrinks and turns into a
''' spiral when damped.
''' The damping here acts on the whole velocity. A spring's damping acts along the spring (on the
''' rate of stretching) and is the same only while the velocity is along the spring: when
''' <see cref="IsExact"/> is false the caller must integrate instead (LinkedSystem).
''' </summary>
Public NotInheritable Class ZeroLengthSpring
    Private ReadOnly _oscillator As DampedOscillator
    Private ReadOnly _equilibrium As Vector
    Private ReadOnly _offset As Vector
    Private ReadOnly _velocity As Vector
    Private ReadOnly _isExact As Boolean

    ''' <summary>The motion from <paramref name="position"/> (m) and <paramref name="velocity"/> (m/s).</summary>
    ''' <param name="anchor">fixed end of the spring, m</param>
    ''' <param name="mass">kg</param>
    ''' <param name="stiffness">k, N/m</param>
    ''' <param name="damping">c ≥ 0, N·s/m</param>
    ''' <param name="gravity">g ≥ 0, m/s², towards −y</param>
    Public Sub New(anchor As Vector, mass As Double, stiffness As Double, damping As Double, gravity As Double,
                   position As Vector, velocity As Vector)
        If Not (gravity >= 0 AndAlso gravity < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(gravity), "must be non-negative and finite")
        _oscillator = New DampedOscillator(mass, stiffness, damping)
        _equilibrium = New Vector(anchor.X, anchor.Y - mass * gravity / stiffness)
        _offset = position - _equilibrium
        _velocity = velocity
        Dim radial = position - anchor
        ' Along-spring damping equals whole-velocity damping when the motion stays on one line through
        ' the anchor: the velocity along the radius, and gravity along it too (vertical, or none).
        Dim onALine = Vector.Cross(radial, velocity) = 0 AndAlso (gravity = 0 OrElse (radial.X = 0 AndAlso velocity.X = 0))
        _isExact = damping = 0 OrElse onALine
    End Sub

    ''' <summary>Where the body hangs at rest, m: mg/k below the anchor.</summary>
    Public ReadOnly Property Equilibrium As Vector
        Get
            Return _equilibrium
        End Get
    End Property

    ''' <summary>The underlying scalar oscillator (ω, γ, regime).</summary>
    Public ReadOnly Property Oscillator As DampedOscillator
        Get
            Return _oscillator
        End Get
    End Property

    ''' <summary>
    ''' True when this motion is the spring's own (damping along the spring): no damping, or a
    ''' motion on one line through the anchor that gravity does not push off it.
    ''' </summary>
    Public ReadOnly Property IsExact As Boolean
        Get
            Return _isExact
        End Get
    End Property

    ''' <summary>Position (m) and velocity (m/s) at time t ≥ 0 (s after the start).</summary>
    Public Sub StateAt(time As Double, ByRef position As Vector, ByRef velocity As Vector)
        Dim p As Double, q As Double, dp As Double, dq As Double
        _oscillator.Propagate(time, p, q, dp, dq)
        position = _equilibrium + p * _offset + q * _velocity
        velocity = dp * _offset + dq * _velocity
    End Sub

    ''' <summary>Position at time t, m.</summary>
    Public Function PositionAt(time As Double) As Vector
        Dim p As Vector, v As Vector
        StateAt(time, p, v)
        Return p
    End Function

    ''' <summary>Velocity at time t, m/s.</summary>
    Public Function VelocityAt(time As Double) As Vector
        Dim p As Vector, v As Vector
        StateAt(time, p, v)
        Return v
    End Function
End Class
