Option Strict On

''' <summary>
''' Pushes overlapping bodies apart before the event-driven solver predicts anything (new bodies,
''' moved bodies, spawn overlaps). Iterative projection: each overlapping pair is separated along its
''' normal, shared in proportion to inverse mass (fixed bodies and the dragged circle do not move),
''' until no overlap exceeds the tolerance. Deterministic; coincident centres get a fixed normal, never NaN.
''' </summary>
Public Module OverlapResolver
    ''' <summary>Separates overlaps in <paramref name="world"/>; returns the deepest overlap left (m).</summary>
    ''' <param name="tolerance">overlap (m) accepted as touching</param>
    ''' <param name="maxIterations">passes before giving up</param>
    Public Function Resolve(world As World, Optional tolerance As Double = 1.0E-12, Optional maxIterations As Integer = 500) As Double
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim circles = world.Circles
        Dim n = circles.Count
        If n = 0 Then Return 0
        Dim dragged = world.DraggedCircle
        Dim rMax = 0.0
        For Each c In circles
            rMax = Math.Max(rMax, c.Radius)
        Next
        Dim cell = 2 * rMax
        Dim worst = 0.0
        For iteration = 1 To maxIterations
            worst = 0
            ' Bucket the circles; pairs are only looked for in neighbouring buckets.
            Dim buckets As New Dictionary(Of Long, List(Of Integer))()
            For i = 0 To n - 1
                Dim key = BucketKey(circles(i).Position, cell, 0, 0)
                Dim list As List(Of Integer) = Nothing
                If Not buckets.TryGetValue(key, list) Then
                    list = New List(Of Integer)()
                    buckets(key) = list
                End If
                list.Add(i)
            Next
            For i = 0 To n - 1
                Dim a = circles(i)
                For ox = -1 To 1
                    For oy = -1 To 1
                        Dim list As List(Of Integer) = Nothing
                        If Not buckets.TryGetValue(BucketKey(a.Position, cell, ox, oy), list) Then Continue For
                        For Each j In list
                            If j <= i Then Continue For
                            worst = Math.Max(worst, Separate(a, circles(j), dragged, tolerance, i, j))
                        Next
                    Next
                Next
            Next
            For Each c In circles
                If c.IsFixed OrElse c Is dragged Then Continue For
                For Each r In world.Rectangles
                    Dim contact = Collider.CircleRectangle(c.Position, c.Radius, r.Min, r.Max)
                    If contact.Depth > tolerance Then
                        worst = Math.Max(worst, contact.Depth)
                        c.Position += contact.Normal * (contact.Depth + 0.5 * tolerance)
                    End If
                Next
                If world.Walls Then
                    Dim inside = world.Inside(c.Position, c.Radius)
                    If inside <> c.Position Then
                        worst = Math.Max(worst, (inside - c.Position).Length)
                        c.Position = inside
                    End If
                End If
            Next
            If worst <= tolerance Then Exit For
        Next
        Return worst
    End Function

    Private Function BucketKey(p As Vector, cell As Double, ox As Integer, oy As Integer) As Long
        Dim ix = CellIndex(p.X, cell) + ox
        Dim iy = CellIndex(p.Y, cell) + oy
        ' Two 32-bit halves: no multiplication, so no overflow however far away a body is.
        Return (ix << 32) Or (iy And &HFFFFFFFFL)
    End Function

    ''' <summary>The cell index, clamped to ±10⁹ so a body 10¹² m away (walls off) cannot overflow it.</summary>
    Private Function CellIndex(v As Double, cell As Double) As Long
        Dim q = Math.Floor(v / cell)
        If Double.IsNaN(q) Then Return 0
        Return CLng(Math.Max(-1000000000.0, Math.Min(1000000000.0, q)))
    End Function

    Private Function Separate(a As Circle, b As Circle, dragged As Circle, tolerance As Double, i As Integer, j As Integer) As Double
        Dim wa = If(a.IsFixed OrElse a Is dragged, 0.0, a.InverseMass)
        Dim wb = If(b.IsFixed OrElse b Is dragged, 0.0, b.InverseMass)
        If wa + wb = 0 Then Return 0
        Dim d = a.Position - b.Position
        Dim dist = d.Length
        Dim depth = a.Radius + b.Radius - dist
        If depth <= tolerance Then Return 0
        ' Coincident centres: a fixed direction that depends only on the pair, so the result is deterministic.
        Dim n As Vector
        If dist > 0 Then
            n = d / dist
        Else
            Dim angle = 2.399963229728653 * (i + 7 * j)
            n = New Vector(Math.Cos(angle), Math.Sin(angle))
        End If
        Dim push = depth + 0.5 * tolerance
        a.Position += n * (push * wa / (wa + wb))
        b.Position -= n * (push * wb / (wa + wb))
        Return depth
    End Function
End Module
