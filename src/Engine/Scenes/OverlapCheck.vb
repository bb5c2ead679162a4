Option Strict On

Namespace Scenes
    ''' <summary>
    ''' Finds the first body (in file order) that overlaps an earlier one by more than 1e-9 m, among pairs
    ''' that collide with each other (any pair but two fixed bodies). Touching is allowed (Newton's
    ''' cradle). A uniform grid keeps it near O(N) for scenes of 100 000 circles; bodies much larger than
    ''' a cell are kept in a short list and checked against everything.
    ''' </summary>
    Friend Module OverlapCheck
        ''' <summary>Overlap allowed for rounding, m.</summary>
        Friend Const Tolerance As Double = 0.000000001

        ''' <summary>A body covering more cells than this goes to the list of large bodies.</summary>
        Private Const MaxCellsPerBody As Long = 16

        ''' <summary>Cell indexes are clamped here so that far-away bodies cannot overflow a Long key.</summary>
        Private Const MaxCellIndex As Double = 1000000000.0

        ''' <summary>Throws a <see cref="SceneFormatException"/> naming both bodies of the first overlap.</summary>
        Friend Sub Check(bodies As IReadOnlyList(Of BodySpec))
            If bodies Is Nothing Then Throw New ArgumentNullException(NameOf(bodies))
            Dim cell = CellSize(bodies)
            If Not (cell > 0) Then cell = 1 ' only segments (no size): any cell will do
            Dim grid As New Dictionary(Of Long, List(Of Integer))(CellKeyComparer.Instance)
            Dim large As New List(Of Integer)
            For j = 0 To bodies.Count - 1
                Dim b = bodies(j)
                Dim ix0 = CellIndex(b.MinX, cell), ix1 = CellIndex(b.MaxX, cell)
                Dim iy0 = CellIndex(b.MinY, cell), iy1 = CellIndex(b.MaxY, cell)
                Dim isLarge = (ix1 - ix0 + 1) * (iy1 - iy0 + 1) > MaxCellsPerBody
                Dim worst = -1 ' the earliest body that j overlaps
                Dim depth = 0.0
                If isLarge Then
                    For i = 0 To j - 1
                        Consider(bodies(i), b, worst, depth)
                    Next
                Else
                    For Each i In large
                        Consider(bodies(i), b, worst, depth)
                    Next
                    For ix = ix0 To ix1
                        For iy = iy0 To iy1
                            Dim members As List(Of Integer) = Nothing
                            If grid.TryGetValue(Key(ix, iy), members) Then
                                For Each i In members
                                    Consider(bodies(i), b, worst, depth)
                                Next
                            End If
                        Next
                    Next
                End If
                If worst >= 0 Then
                    Throw New SceneFormatException(b.Place, "overlaps " & bodies(worst).Place & " by " & SceneReader.Brief(depth) & " m")
                End If
                If isLarge Then
                    large.Add(j)
                Else
                    For ix = ix0 To ix1
                        For iy = iy0 To iy1
                            Dim k = Key(ix, iy)
                            Dim members As List(Of Integer) = Nothing
                            If Not grid.TryGetValue(k, members) Then
                                members = New List(Of Integer)
                                grid.Add(k, members)
                            End If
                            members.Add(j)
                        Next
                    Next
                End If
            Next
        End Sub

        ''' <summary>Keeps the earliest earlier body <paramref name="a"/> that <paramref name="b"/> overlaps.</summary>
        Private Sub Consider(a As BodySpec, b As BodySpec, ByRef worst As Integer, ByRef depth As Double)
            If worst >= 0 AndAlso a.Index >= worst Then Return
            Dim d = OverlapDepth(a, b)
            If d > Tolerance Then
                worst = a.Index
                depth = d
            End If
        End Sub

        ''' <summary>
        ''' How deep two bodies overlap, m (≤ 0 when apart, and 0 for two fixed bodies, which never collide
        ''' and so may overlap). Circles by their centres; any other pair through the Minkowski difference
        ''' of their outlines (see <see cref="OutlineContact.Penetration"/>).
        ''' </summary>
        Friend Function OverlapDepth(a As BodySpec, b As BodySpec) As Double
            If a.IsFixed AndAlso b.IsFixed Then Return 0
            If a.Kind = ShapeKind.Circle AndAlso b.Kind = ShapeKind.Circle Then
                Return a.Radius + b.Radius - Vector.Hypot(a.X - b.X, a.Y - b.Y)
            End If
            Dim k = Outline.MinkowskiDifference(b.Outline, a.Outline)
            Return OutlineContact.Penetration(k, a.Position - b.Position).Depth
        End Function

        ''' <summary>Twice the median half-size of the bodies (the larger side of each one's bounding box), m; 0 when there are none.</summary>
        Private Function CellSize(bodies As IReadOnlyList(Of BodySpec)) As Double
            Dim sizes As New List(Of Double)
            For Each b In bodies
                sizes.Add(Math.Max(b.MaxX - b.MinX, b.MaxY - b.MinY) / 2)
            Next
            If sizes.Count = 0 Then Return 0
            sizes.Sort()
            Return 2 * sizes(sizes.Count \ 2)
        End Function

        Private Function CellIndex(v As Double, cell As Double) As Long
            Dim q = Math.Floor(v / cell)
            If Double.IsNaN(q) Then Return 0 ' ∞/∞: radii near the largest double make the cell infinite
            Return CLng(Math.Max(-MaxCellIndex, Math.Min(MaxCellIndex, q)))
        End Function

        Private Function Key(ix As Long, iy As Long) As Long
            Return (ix << 32) Or (iy And &HFFFFFFFFL)
        End Function

        ''' <summary>
        ''' Long's own hash is high word Xor low word, which sends every cell (i, j) with the same i Xor j
        ''' to one bucket; this spreads cells with large primes (Teschner et al., 2003) so the grid stays
        ''' O(1) per cell. |i|, |j| ≤ 1e9, so the products cannot overflow.
        ''' </summary>
        Private NotInheritable Class CellKeyComparer
            Implements IEqualityComparer(Of Long)

            Friend Shared ReadOnly Instance As New CellKeyComparer()

            Public Overloads Function Equals(x As Long, y As Long) As Boolean Implements IEqualityComparer(Of Long).Equals
                Return x = y
            End Function

            Public Overloads Function GetHashCode(obj As Long) As Integer Implements IEqualityComparer(Of Long).GetHashCode
                Dim ix = obj >> 32
                Dim iy = obj And &HFFFFFFFFL
                If iy > Integer.MaxValue Then iy -= &H100000000L
                Return CInt(((ix * 73856093L) Xor (iy * 19349663L)) And &H7FFFFFFFL)
            End Function
        End Class
    End Module
End Namespace
