Option Strict On

''' <summary>What <see cref="ContactCluster.Resolve"/> returns: new velocities and the impulse on each contact.</summary>
Public NotInheritable Class ClusterResolution
    Private ReadOnly _velocities As Vector()
    Private ReadOnly _impulses As Double()

    Friend Sub New(velocities As Vector(), impulses As Double(), separated As Boolean, reprojected As Boolean)
        _velocities = velocities
        _impulses = impulses
        Me.Separated = separated
        Me.Reprojected = reprojected
    End Sub

    ''' <summary>The bodies' velocities afterwards (m/s), in the order given; immovable bodies keep theirs.</summary>
    Public ReadOnly Property Velocities As IReadOnlyList(Of Vector)
        Get
            Return _velocities
        End Get
    End Property

    ''' <summary>
    ''' The total impulse each contact gave (N·s, ≥ 0, on A along the normal and on B against it), in the
    ''' order given: the size of the collision to report for that contact. Zero for a contact that did
    ''' not push. Where contacts are redundant (two supports along one line) the split between them is
    ''' one of many that give the same velocities. Each is accurate to about 10⁻¹⁵ of the largest impulse
    ''' in the cluster: a tiny impulse beside a huge one is known only to that absolute accuracy.
    ''' </summary>
    Public ReadOnly Property Impulses As IReadOnlyList(Of Double)
        Get
            Return _impulses
        End Get
    End Property

    ''' <summary>
    ''' True when afterwards no contact approaches faster than <see cref="ContactCluster.ApproachTolerance"/>
    ''' times the speed scale. False when no velocities can satisfy every contact (immovable bodies
    ''' closing in on a movable one, or a contact between two immovable bodies that approach) or, as a
    ''' guard that rounding cannot trip in practice, when the solve reached its cap.
    ''' </summary>
    Public ReadOnly Property Separated As Boolean

    ''' <summary>
    ''' True when restitution left some contact approaching (one that did not push during compression
    ''' but is pushed into by the rebound of another) and the rebound was projected once more. Kinetic
    ''' energy is then lost even for e = 1.
    ''' </summary>
    Public ReadOnly Property Reprojected As Boolean
End Class
