Option Strict On

''' <summary>
''' Dot products of vectors over a group's bodies laid out as the constraint rows lay them out (per body: x, y),
''' in the metric of the constraint matrix M = J W Jᵀ or with every movable body weighing the same. A body that
''' cannot move (inverse mass 0) is left out of both.
''' </summary>
Friend Module MassMetric
    ''' <summary>Σ w_k (x_k · y_k) over the bodies k, w the inverse mass (1/kg).</summary>
    Friend Function Weighted(inverseMass As Double(), x As Double(), y As Double()) As Double
        Dim s = 0.0
        For k = 0 To inverseMass.Length - 1
            Dim w = inverseMass(k)
            If w = 0 Then Continue For
            s += w * (x(2 * k) * y(2 * k) + x(2 * k + 1) * y(2 * k + 1))
        Next
        Return s
    End Function

    ''' <summary>Σ x_k · y_k over the bodies k that can move, each weighing the same.</summary>
    Friend Function Unit(inverseMass As Double(), x As Double(), y As Double()) As Double
        Dim s = 0.0
        For k = 0 To inverseMass.Length - 1
            If inverseMass(k) = 0 Then Continue For
            s += x(2 * k) * y(2 * k) + x(2 * k + 1) * y(2 * k + 1)
        Next
        Return s
    End Function

    ''' <summary>
    ''' Σ w_k (x_k · y_k) over <paramref name="bodies"/> only (movable, in increasing order): the same sum, term for
    ''' term, as over every body where x or y is zero on all the others.
    ''' </summary>
    Friend Function Weighted(inverseMass As Double(), x As Double(), y As Double(), bodies As Integer()) As Double
        Dim s = 0.0
        For Each k In bodies
            s += inverseMass(k) * (x(2 * k) * y(2 * k) + x(2 * k + 1) * y(2 * k + 1))
        Next
        Return s
    End Function

    ''' <summary>Σ x_k · y_k over <paramref name="bodies"/> only (movable, in increasing order), each weighing the same.</summary>
    Friend Function Unit(x As Double(), y As Double(), bodies As Integer()) As Double
        Dim s = 0.0
        For Each k In bodies
            s += x(2 * k) * y(2 * k) + x(2 * k + 1) * y(2 * k + 1)
        Next
        Return s
    End Function
End Module
