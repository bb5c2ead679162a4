Option Strict On

''' <summary>
''' The Minkowski differences of the pairs of outlines a stepping solver meets, kept
''' between steps. Nothing rotates, so a body's outline never changes and the difference of two outlines
''' is the same every step: making it again (a merge of their edges into a new outline) for every box
''' resting on a floor, every step, would be most of the cost of the contact. Keyed by the two outline
''' objects themselves; a world whose bodies keep changing cannot make it grow without bound, because it
''' is emptied when it holds more than <see cref="Capacity"/> pairs.
''' </summary>
Friend NotInheritable Class DifferenceCache
    ''' <summary>The most pairs kept; more than a scene meets in one step unless it has thousands of shapes.</summary>
    Friend Const Capacity As Integer = 8192

    Private ReadOnly _pairs As New Dictionary(Of OutlinePair, (Difference As Outline, CoreDifference As Outline))(OutlinePair.Comparer)

    ''' <summary>
    ''' <c>Outline.MinkowskiDifference(b, a)</c> (body A touches body B when p_A − p_B lies in it) and
    ''' <c>Outline.MinkowskiDifference(b, Collider.OutlineCore(a))</c> (A's core is inside B), for
    ''' <see cref="Collider.OutlineOutlineFrom(Outline, Outline, Vector, Vector, Vector)"/>.
    ''' </summary>
    Friend Function [Get](b As Outline, a As Outline) As (Difference As Outline, CoreDifference As Outline)
        Dim key As New OutlinePair(b, a)
        Dim found As (Difference As Outline, CoreDifference As Outline) = Nothing
        If _pairs.TryGetValue(key, found) Then Return found
        If _pairs.Count >= Capacity Then _pairs.Clear()
        Dim difference = Outline.MinkowskiDifference(b, a)
        ' With no rounding on A (a box, a polygon) A's core is A itself, and the two differences are one.
        Dim core = Collider.OutlineCore(a)
        found = (difference, If(core Is a, difference, Outline.MinkowskiDifference(b, core)))
        _pairs.Add(key, found)
        Return found
    End Function

    ''' <summary>Forgets every pair (the world's bodies were replaced).</summary>
    Friend Sub Clear()
        _pairs.Clear()
    End Sub

    ''' <summary>Two outlines, compared by identity (an outline is immutable, so the same object is the same shape).</summary>
    Private Structure OutlinePair
        Friend ReadOnly B As Outline
        Friend ReadOnly A As Outline

        Friend Sub New(b As Outline, a As Outline)
            Me.B = b
            Me.A = a
        End Sub

        Friend Shared ReadOnly Comparer As New IdentityComparer()

        Friend NotInheritable Class IdentityComparer
            Implements IEqualityComparer(Of OutlinePair)

            Public Overloads Function Equals(x As OutlinePair, y As OutlinePair) As Boolean Implements IEqualityComparer(Of OutlinePair).Equals
                Return x.B Is y.B AndAlso x.A Is y.A
            End Function

            Public Overloads Function GetHashCode(obj As OutlinePair) As Integer Implements IEqualityComparer(Of OutlinePair).GetHashCode
                Dim hb = Runtime.CompilerServices.RuntimeHelpers.GetHashCode(obj.B)
                Dim ha = Runtime.CompilerServices.RuntimeHelpers.GetHashCode(obj.A)
                Return (hb * 397) Xor ha
            End Function
        End Class
    End Structure
End Class
