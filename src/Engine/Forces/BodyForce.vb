Option Strict On

''' <summary>One force on a body, as a free-body diagram shows it: its kind, what exerts it, the force and where it acts.</summary>
Public NotInheritable Class BodyForce
    ''' <summary>A force of <paramref name="kind"/> exerted by <paramref name="source"/>: <paramref name="force"/> (N) acting at <paramref name="point"/> (m).</summary>
    Public Sub New(kind As ForceKind, source As String, force As Vector, point As Vector)
        Me.Kind = kind
        Me.Source = source
        Me.Force = force
        Me.Point = point
    End Sub

    ''' <summary>Which kind of force.</summary>
    Public ReadOnly Property Kind As ForceKind

    ''' <summary>What exerts it: "Earth", "air", a body's, link's or liquid's id, or a wall ("floor", "left wall").</summary>
    Public ReadOnly Property Source As String

    ''' <summary>The force, N.</summary>
    Public ReadOnly Property Force As Vector

    ''' <summary>Where it acts, m: the centre of mass, or for a contact the middle of where the surfaces touch.</summary>
    Public ReadOnly Property Point As Vector

    ''' <summary>|F|, N.</summary>
    Public ReadOnly Property Magnitude As Double
        Get
            Return Force.Length
        End Get
    End Property
End Class
