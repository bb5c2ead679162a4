Option Strict On

''' <summary>
''' One contact of a cluster resolved by <see cref="ContactCluster.Resolve"/>: body A touches body B
''' (or the world) along a unit normal that points from B towards A, as in <see cref="Impulse.Resolve"/>.
''' </summary>
Public Structure ClusterContact
    Implements IEquatable(Of ClusterContact)

    ''' <summary>The value of <see cref="BodyB"/> for a wall or fixed obstacle that is not one of the bodies.</summary>
    Public Const World As Integer = -1

    ''' <summary>Index of body A among the cluster's bodies.</summary>
    Public ReadOnly Property BodyA As Integer
    ''' <summary>Index of body B among the cluster's bodies, or <see cref="World"/>.</summary>
    Public ReadOnly Property BodyB As Integer
    ''' <summary>Unit normal from B towards A: the direction in which the contact pushes A.</summary>
    Public ReadOnly Property Normal As Vector

    ''' <summary>Makes a contact between bodies A and B (or <see cref="World"/>) with the unit normal from B towards A.</summary>
    Public Sub New(bodyA As Integer, bodyB As Integer, normal As Vector)
        Me.BodyA = bodyA
        Me.BodyB = bodyB
        Me.Normal = normal
    End Sub

    ''' <summary>Exact equality of the bodies and the normal.</summary>
    Public Overloads Function Equals(other As ClusterContact) As Boolean Implements IEquatable(Of ClusterContact).Equals
        Return BodyA = other.BodyA AndAlso BodyB = other.BodyB AndAlso Normal.Equals(other.Normal)
    End Function

    Public Overrides Function Equals(obj As Object) As Boolean
        Return TypeOf obj Is ClusterContact AndAlso Equals(DirectCast(obj, ClusterContact))
    End Function

    Public Overrides Function GetHashCode() As Integer
        Return (BodyA * 397 Xor BodyB) * 397 Xor Normal.GetHashCode()
    End Function

    Public Shared Operator =(a As ClusterContact, b As ClusterContact) As Boolean
        Return a.Equals(b)
    End Operator

    Public Shared Operator <>(a As ClusterContact, b As ClusterContact) As Boolean
        Return Not a.Equals(b)
    End Operator
End Structure
