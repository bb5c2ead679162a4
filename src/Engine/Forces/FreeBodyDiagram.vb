Option Strict On

''' <summary>
''' Every force on one body at one instant (<see cref="BodyForces"/>), their sum, and the body's mass and
''' acceleration: Newton's second law says the sum is m a, and the two are found so that it holds.
''' </summary>
Public NotInheritable Class FreeBodyDiagram
    ''' <summary>The diagram of <paramref name="body"/>: <paramref name="forces"/> on it and its <paramref name="acceleration"/> (m/s²).</summary>
    Public Sub New(body As Shape, forces As IReadOnlyList(Of BodyForce), acceleration As Vector)
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If forces Is Nothing Then Throw New ArgumentNullException(NameOf(forces))
        Me.Body = body
        Me.Forces = forces
        Me.Acceleration = acceleration
        Dim total = Vector.Zero
        For Each f In forces
            total += f.Force
        Next
        Sum = total
    End Sub

    ''' <summary>The body.</summary>
    Public ReadOnly Property Body As Shape

    ''' <summary>The forces on it, weight first, then the known forces, then contacts and links.</summary>
    Public ReadOnly Property Forces As IReadOnlyList(Of BodyForce)

    ''' <summary>ΣF, N.</summary>
    Public ReadOnly Property Sum As Vector

    ''' <summary>a, m/s²: what the forces give it.</summary>
    Public ReadOnly Property Acceleration As Vector

    ''' <summary>m a, N.</summary>
    Public ReadOnly Property MassTimesAcceleration As Vector
        Get
            Return Acceleration * Body.Mass
        End Get
    End Property
End Class
