Option Strict On

''' <summary>
''' The momenta diagram (as in PhET's Collision Lab): each movable body's momentum drawn tip to tail
''' in the body's colour, and their sum Σp as one arrow from the first tail to the last tip. The
''' chain shows that the sum is the same before and after a collision even though each body's
''' momentum changes. Points are in kg·m/s, from the origin (0, 0) at the first tail.
''' </summary>
Public NotInheritable Class MomentaDiagram
    ''' <summary>With more movable bodies than this only the sum is drawn (a gas's chain would be a scribble).</summary>
    Public Const MaxArrows As Integer = 40

    Private ReadOnly _colours As New List(Of String)
    Private ReadOnly _momenta As New List(Of Vector)

    ''' <summary>The diagram of <paramref name="world"/>'s movable bodies now.</summary>
    Public Sub New(world As World)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim px = 0.0, py = 0.0
        Dim movables = world.Movables
        BodyCount = movables.Count
        For Each b In movables
            Dim p = b.Mass * b.Velocity
            px += p.X
            py += p.Y
            If movables.Count <= MaxArrows Then
                _colours.Add(If(b.Color, ""))
                _momenta.Add(p)
            End If
        Next
        Sum = New Vector(px, py)
        ' The chain's extent from the origin, kg·m/s: the scale must fit every tip, not only the sum.
        Dim tip = Vector.Zero, far = Sum.Length
        For Each p In _momenta
            tip += p
            far = Math.Max(far, tip.Length)
        Next
        Extent = far
    End Sub

    ''' <summary>Movable bodies in the world.</summary>
    Public ReadOnly Property BodyCount As Integer

    ''' <summary>True when every body has its own arrow (at most <see cref="MaxArrows"/> bodies).</summary>
    Public ReadOnly Property ShowsEachBody As Boolean
        Get
            Return BodyCount <= MaxArrows
        End Get
    End Property

    ''' <summary>Σp, kg·m/s.</summary>
    Public ReadOnly Property Sum As Vector

    ''' <summary>The farthest any tip (or the sum's) is from the origin, kg·m/s.</summary>
    Public ReadOnly Property Extent As Double

    ''' <summary>Arrows in the chain (0 when only the sum is drawn).</summary>
    Public ReadOnly Property Count As Integer
        Get
            Return _momenta.Count
        End Get
    End Property

    ''' <summary>The body's momentum of arrow <paramref name="index"/>, kg·m/s.</summary>
    Public Function Momentum(index As Integer) As Vector
        Return _momenta(index)
    End Function

    ''' <summary>The body's colour ("#rrggbb") of arrow <paramref name="index"/>.</summary>
    Public Function Colour(index As Integer) As String
        Return _colours(index)
    End Function

    ''' <summary>Where arrow <paramref name="index"/> starts: the sum of the momenta before it, kg·m/s.</summary>
    Public Function Tail(index As Integer) As Vector
        Dim t = Vector.Zero
        For i = 0 To index - 1
            t += _momenta(i)
        Next
        Return t
    End Function
End Class
