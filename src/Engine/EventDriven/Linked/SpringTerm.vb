Option Strict On

''' <summary>
''' The spring term of a group's equations of motion: Hooke's law with the spring's damping, k (d − L) + c ḋ
''' along the line of its ends (docs/links.md), added to the acceleration of a state laid out as the integrators
''' lay it out (per body: centre x, y, then vx, vy). One formula for every motion that integrates or snapshots a
''' group with springs, so that they all round it the same way.
''' </summary>
Friend Module SpringTerm
    ''' <summary>A few units in the last place of a double, relative: the rounding of the operations in a spring's pull.</summary>
    Friend Const Ulps As Double = 4 * 2.2204460492503131E-16

    ''' <summary>
    ''' The pull (N) of spring <paramref name="l"/> on its end A, whose centre is at <paramref name="pa"/> (m) moving
    ''' at <paramref name="va"/> (m/s), towards end B at <paramref name="pb"/> moving at <paramref name="vb"/>:
    ''' (k (d − L) + c ḋ) / d times r = pb − pa, with d = |r| and ḋ = (vb − va)·r / d. B feels the opposite pull.
    ''' Zero when the ends coincide: the line of the ends has no direction there.
    ''' </summary>
    Friend Function Pull(l As Link, pa As Vector, va As Vector, pb As Vector, vb As Vector) As Vector
        Dim r = pb - pa
        Dim dist = r.Length
        If dist = 0 Then Return Vector.Zero
        Return r * ((l.Stiffness * (dist - l.Length) + l.Damping * Vector.Dot(vb - va, r) / dist) / dist)
    End Function

    ''' <summary>
    ''' Adds every spring of <paramref name="springs"/> to <paramref name="d"/>, dy/dt of state <paramref name="y"/>
    ''' of <paramref name="bodies"/>: its pull ÷ mass on each end that is among them. An end that is not (fixed,
    ''' or an anchor) stays at its own point, still.
    ''' </summary>
    Friend Sub Add(springs As IEnumerable(Of Link), bodies As Shape(), y As Double(), d As Double())
        For Each l In springs
            Dim a As Integer, b As Integer, pa As Vector, va As Vector, pb As Vector, vb As Vector
            Ends(l, bodies, y, a, b, pa, va, pb, vb)
            Dim force = Pull(l, pa, va, pb, vb)
            d(4 * a + 2) += force.X * bodies(a).InverseMass
            d(4 * a + 3) += force.Y * bodies(a).InverseMass
            If b >= 0 Then
                d(4 * b + 2) -= force.X * bodies(b).InverseMass
                d(4 * b + 3) -= force.Y * bodies(b).InverseMass
            End If
        Next
    End Sub

    ''' <summary>
    ''' Adds to <paramref name="rounding"/> how far each spring's pull ÷ mass in <see cref="Add"/> may be off by
    ''' rounding alone at state <paramref name="y"/> (m/s², on the velocity components): a few units in the last
    ''' place of k (|p_A| + |p_B| + L) + c (|v_A| + |v_B|), the sizes of the numbers whose difference the pull is. At
    ''' a stiff spring's length that difference is all rounding, and the integrator's error control must not chase it.
    ''' </summary>
    Friend Sub AddRounding(springs As IEnumerable(Of Link), bodies As Shape(), y As Double(), rounding As Double())
        For Each l In springs
            Dim a As Integer, b As Integer, pa As Vector, va As Vector, pb As Vector, vb As Vector
            Ends(l, bodies, y, a, b, pa, va, pb, vb)
            Dim size = Ulps * (l.Stiffness * (pa.Length + pb.Length + l.Length) + l.Damping * (va.Length + vb.Length))
            rounding(4 * a + 2) += size * bodies(a).InverseMass
            rounding(4 * a + 3) += size * bodies(a).InverseMass
            If b >= 0 Then
                rounding(4 * b + 2) += size * bodies(b).InverseMass
                rounding(4 * b + 3) += size * bodies(b).InverseMass
            End If
        Next
    End Sub

    ''' <summary>
    ''' The energy stored in <paramref name="springs"/> at state <paramref name="y"/> of <paramref name="bodies"/>, J:
    ''' Σ ½ k (d − L)², the ends read as <see cref="Add"/> reads them.
    ''' </summary>
    Friend Function Energy(springs As IEnumerable(Of Link), bodies As Shape(), y As Double()) As Double
        Dim sum = 0.0
        For Each l In springs
            Dim a As Integer, b As Integer, pa As Vector, va As Vector, pb As Vector, vb As Vector
            Ends(l, bodies, y, a, b, pa, va, pb, vb)
            Dim stretch = (pb - pa).Length - l.Length
            sum += 0.5 * l.Stiffness * stretch * stretch
        Next
        Return sum
    End Function

    ''' <summary>
    ''' Spring <paramref name="l"/>'s ends in state <paramref name="y"/> of <paramref name="bodies"/>: their slots
    ''' <paramref name="a"/> and <paramref name="b"/> (−1 for an end that is not among them, fixed or an anchor, which
    ''' stays at its own point, still), positions (m) and velocities (m/s).
    ''' </summary>
    Private Sub Ends(l As Link, bodies As Shape(), y As Double(), ByRef a As Integer, ByRef b As Integer,
                     ByRef pa As Vector, ByRef va As Vector, ByRef pb As Vector, ByRef vb As Vector)
        a = Array.IndexOf(bodies, l.A)
        b = If(l.IsAnchored, -1, Array.IndexOf(bodies, l.B))
        pa = New Vector(y(4 * a), y(4 * a + 1))
        va = New Vector(y(4 * a + 2), y(4 * a + 3))
        pb = If(b >= 0, New Vector(y(4 * b), y(4 * b + 1)), l.EndB)
        vb = If(b >= 0, New Vector(y(4 * b + 2), y(4 * b + 3)), Vector.Zero)
    End Sub
End Module
