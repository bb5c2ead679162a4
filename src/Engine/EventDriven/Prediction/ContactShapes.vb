Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' The Minkowski differences K = B ⊕ (−A) of the pairs of outlines the solver meets, made once and
''' kept: nothing rotates, so a pair's K never changes. Keyed by the two outline objects (bodies of
''' the same shape share nothing, but a scene has few distinct pairs that are not two circles).
''' </summary>
Friend NotInheritable Class ContactShapes
    Private ReadOnly _cache As New Dictionary(Of (Outline, Outline), Outline)(PairComparer.Instance)

    ''' <summary>K = b ⊕ (−a), with radius R_a + R_b.</summary>
    Friend Function Difference(b As Outline, a As Outline) As Outline
        Dim k As Outline = Nothing
        If _cache.TryGetValue((b, a), k) Then Return k
        k = Outline.MinkowskiDifference(b, a)
        _cache((b, a)) = k
        Return k
    End Function

    ''' <summary>Forgets every pair (the bodies were reloaded).</summary>
    Friend Sub Clear()
        _cache.Clear()
    End Sub

    ''' <summary>Pairs compared by reference: an outline is never equal to another object.</summary>
    Private NotInheritable Class PairComparer
        Implements IEqualityComparer(Of (Outline, Outline))

        Friend Shared ReadOnly Instance As New PairComparer()

        Public Overloads Function Equals(x As (Outline, Outline), y As (Outline, Outline)) As Boolean Implements IEqualityComparer(Of (Outline, Outline)).Equals
            Return x.Item1 Is y.Item1 AndAlso x.Item2 Is y.Item2
        End Function

        Public Overloads Function GetHashCode(obj As (Outline, Outline)) As Integer Implements IEqualityComparer(Of (Outline, Outline)).GetHashCode
            Return RuntimeHelpers.GetHashCode(obj.Item1) * 397 Xor RuntimeHelpers.GetHashCode(obj.Item2)
        End Function
    End Class
End Class
