Option Strict On

''' <summary>
''' One body's impulse at one collision, as it is drawn for a moment: Δp = m·(v_after − v_before),
''' an arrow from the point of contact, fading as it ages.
''' </summary>
Public NotInheritable Class ImpulseMark
    Friend Sub New(body As Shape, other As Shape, wall As WallSide, impulse As Vector, time As Double)
        Me.Body = body
        Me.Other = other
        Me.Wall = wall
        Me.Impulse = impulse
        Me.Time = time
        At = body.CentreOfMass
    End Sub

    ''' <summary>The body that received the impulse.</summary>
    Public ReadOnly Property Body As Shape
    ''' <summary>What it hit: another body, or Nothing for a side of the container (see <see cref="Wall"/>).</summary>
    Public ReadOnly Property Other As Shape
    ''' <summary>Which side of the container, when <see cref="Other"/> is Nothing.</summary>
    Public ReadOnly Property Wall As WallSide
    ''' <summary>Δp = m·(v_after − v_before), kg·m/s (N·s).</summary>
    Public ReadOnly Property Impulse As Vector
    ''' <summary>Simulated time of the collision, s.</summary>
    Public ReadOnly Property Time As Double
    ''' <summary>Where the arrow starts: the point of contact, m (see <see cref="ImpulseMarks.Locate"/>).</summary>
    Public Property At As Vector
    ''' <summary>Real seconds since it was recorded.</summary>
    Public Property Age As Double
    ''' <summary>False until <see cref="At"/> has been worked out from the bodies' positions after the frame.</summary>
    Public Property IsLocated As Boolean
End Class
