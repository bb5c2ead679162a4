Option Strict On
Imports Xunit

''' <summary>
''' The submerged area and its first moment for a circle, a box and a polygon, against closed forms where
''' there are some and against an independent numerical integral (Simpson's rule over the chord lengths)
''' for random rectangles; and buoyancy's potential against its force.
''' </summary>
Public Class SubmergedAreaTests
    Private Const Deep As Double = 100

    <Fact>
    Public Sub ABox_PartlyUnderTheSurface_HasItsWidthTimesTheDepth()
        Dim box = Outline.Box(0.5, 0.4)
        Dim part = SubmergedArea.Inside(box, New Vector(1, 0.9), New Vector(0, 0), New Vector(4, 1.05))
        Assert.Equal(0.5 * 0.15, part.Area, 14)
        Assert.Equal(0.5 * 0.15 * 0.975, part.MomentY, 14)
        Assert.Equal(0.0, SubmergedArea.Inside(box, New Vector(1, 1.05), New Vector(0, 0), New Vector(4, 1.05)).Area)
        Assert.Equal(0.2, SubmergedArea.Inside(box, New Vector(1, 0.1), New Vector(0, 0), New Vector(4, 1.05)).Area, 15)
    End Sub

    <Fact>
    Public Sub ACircle_HalfOrQuarterOrWhollyInside()
        Dim r = 0.3, c = New Vector(2, 1)
        Dim disc = Outline.Point(r)
        Dim half = SubmergedArea.Inside(disc, c, New Vector(-Deep, -Deep), New Vector(Deep, 1))
        Assert.Equal(Math.PI * r * r / 2, half.Area, 14)
        ' Its centroid 4r/(3π) below the centre.
        Assert.Equal(1 - 4 * r / (3 * Math.PI), half.MomentY / half.Area, 14)
        Dim quarter = SubmergedArea.Inside(disc, c, New Vector(2, -Deep), New Vector(Deep, 1))
        Assert.Equal(Math.PI * r * r / 4, quarter.Area, 14)
        Dim whole = SubmergedArea.Inside(disc, c, New Vector(0, 0), New Vector(4, 4))
        Assert.Equal(Math.PI * r * r, whole.Area, 14)
        Assert.Equal(Math.PI * r * r, whole.MomentY, 14)
        Assert.Equal(0.0, SubmergedArea.Inside(disc, c, New Vector(0, 0), New Vector(4, 0.7)).Area)
        ' A rectangle wholly inside the disc.
        Dim tiny = SubmergedArea.Inside(disc, c, New Vector(2, 1), New Vector(2.1, 1.05))
        Assert.Equal(0.005, tiny.Area, 15)
        Assert.Equal(0.005 * 1.025, tiny.MomentY, 15)
    End Sub

    ''' <summary>∫ over x of the clipped vertical extent (and of its moment), by Simpson's rule on a fine grid, between the kinks.</summary>
    Private Shared Sub Numerically(chord As Func(Of Double, (Lo As Double, Hi As Double)), a As Double, b As Double, ByRef area As Double, ByRef moment As Double)
        area = 0 : moment = 0
        If b <= a Then Return
        Dim n = 200000
        Dim h = (b - a) / n
        For k = 0 To n
            Dim x = a + k * h
            Dim c = chord(x)
            Dim len = Math.Max(c.Hi - c.Lo, 0)
            Dim mom = If(len > 0, 0.5 * (c.Hi * c.Hi - c.Lo * c.Lo), 0)
            Dim w = If(k = 0 OrElse k = n, 1, If(k Mod 2 = 1, 4, 2))
            area += w * len
            moment += w * mom
        Next
        area *= h / 3
        moment *= h / 3
    End Sub

    <Fact>
    Public Sub ACircle_InRandomRectangles_MatchesTheIntegral()
        Dim rng As New Random(28)
        For trial = 1 To 40
            Dim r = 0.1 + rng.NextDouble()
            Dim c = New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)
            Dim lo = New Vector(rng.NextDouble() * 4 - 3, rng.NextDouble() * 4 - 3)
            Dim hi = lo + New Vector(rng.NextDouble() * 3, rng.NextDouble() * 3)
            Dim part = SubmergedArea.Inside(Outline.Point(r), c, lo, hi)
            ' Kinks of the chord: the rectangle's sides and where its top and bottom cut the circle; integrate between them.
            Dim xs As New List(Of Double) From {c.X - r, c.X + r, lo.X, hi.X}
            For Each y In {lo.Y, hi.Y}
                Dim d = r * r - (y - c.Y) * (y - c.Y)
                If d > 0 Then xs.Add(c.X - Math.Sqrt(d)) : xs.Add(c.X + Math.Sqrt(d))
            Next
            xs = xs.Where(Function(x) x >= Math.Max(c.X - r, lo.X) AndAlso x <= Math.Min(c.X + r, hi.X)).Distinct().OrderBy(Function(x) x).ToList()
            Dim area = 0.0, moment = 0.0
            For k = 0 To xs.Count - 2
                Dim a1 As Double, m1 As Double
                Numerically(Function(x)
                                Dim half = Math.Sqrt(Math.Max(r * r - (x - c.X) * (x - c.X), 0))
                                Return (Math.Max(c.Y - half, lo.Y), Math.Min(c.Y + half, hi.Y))
                            End Function, xs(k), xs(k + 1), a1, m1)
                area += a1 : moment += m1
            Next
            Assert.True(Math.Abs(part.Area - area) < 0.00000001, $"trial {trial}: area {part.Area} against {area}")
            Assert.True(Math.Abs(part.MomentY - moment) < 0.00000001, $"trial {trial}: moment {part.MomentY} against {moment}")
        Next
    End Sub

    <Fact>
    Public Sub APolygon_MatchesTheIntegral()
        Dim triangle = Outline.Polygon({New Vector(0, 0), New Vector(2, 0), New Vector(0.5, 1.5)})
        Dim core = triangle.Translated(-triangle.Centroid)
        Dim position = New Vector(3, 2) ' centroid there
        Dim lo = New Vector(2.2, 1.2), hi = New Vector(5, 2.4)
        Dim part = SubmergedArea.Inside(core, position, lo, hi)
        ' The triangle in absolute coordinates: (3,2) + (v − centroid).
        Dim v = core.Vertices.Select(Function(p) p + position).ToArray()
        Dim chord = Function(x As Double) As (Lo As Double, Hi As Double)
                        ' Vertical extent of the triangle at x: intersect with each edge.
                        Dim ys As New List(Of Double)
                        For i = 0 To 2
                            Dim p = v(i), q = v((i + 1) Mod 3)
                            If (p.X - x) * (q.X - x) <= 0 AndAlso p.X <> q.X Then ys.Add(p.Y + (q.Y - p.Y) * (x - p.X) / (q.X - p.X))
                        Next
                        If ys.Count = 0 Then Return (0.0, 0.0)
                        Return (Math.Max(ys.Min(), lo.Y), Math.Min(ys.Max(), hi.Y))
                    End Function
        Dim xs = v.Select(Function(p) p.X).Concat({lo.X, hi.X}).Where(Function(x) x >= Math.Max(lo.X, v.Min(Function(p) p.X)) AndAlso x <= Math.Min(hi.X, v.Max(Function(p) p.X))).Distinct().OrderBy(Function(x) x).ToList()
        ' Add where the top and bottom of the rectangle cut the edges.
        For Each y In {lo.Y, hi.Y}
            For i = 0 To 2
                Dim p = v(i), q = v((i + 1) Mod 3)
                If (p.Y - y) * (q.Y - y) < 0 Then xs.Add(p.X + (q.X - p.X) * (y - p.Y) / (q.Y - p.Y))
            Next
        Next
        xs = xs.Where(Function(x) x >= lo.X AndAlso x <= hi.X).Distinct().OrderBy(Function(x) x).ToList()
        Dim area = 0.0, moment = 0.0
        For k = 0 To xs.Count - 2
            Dim a1 As Double, m1 As Double
            Numerically(chord, xs(k), xs(k + 1), a1, m1)
            area += a1 : moment += m1
        Next
        Assert.True(Math.Abs(part.Area - area) < 0.00000001, $"area {part.Area} against {area}")
        Assert.True(Math.Abs(part.MomentY - moment) < 0.00000001, $"moment {part.MomentY} against {moment}")
    End Sub

    <Fact>
    Public Sub BuoyancysPotential_FallsAsTheForcePushesUp()
        ' −dU/dy = ρ g A_sub, by central differences, for a box and a circle crossing the surface.
        Dim rho = 1000.0, g = 9.81, surface = 1.5
        For Each shape In {Outline.Box(0.5, 0.4), Outline.Point(0.25)}
            For Each y In {1.2, 1.35, 1.4}
                Dim h = 0.000001
                Dim potential = Function(py As Double) Buoyancy.Potential(rho, g, surface, SubmergedArea.Inside(shape, New Vector(2, py), New Vector(0, 0), New Vector(4, surface)))
                Dim slope = (potential(y + h) - potential(y - h)) / (2 * h)
                Dim force = Buoyancy.Force(rho, g, SubmergedArea.Inside(shape, New Vector(2, y), New Vector(0, 0), New Vector(4, surface)))
                Assert.True(Math.Abs(-slope - force) < 0.000001 * force, $"{-slope} against {force}")
            Next
        Next
        Assert.Equal(0.2, Buoyancy.FloatingDepth(100, 0.5, 1000), 15)
        Assert.Equal(2 * Math.PI * Math.Sqrt(100 / (1000 * 9.81 * 0.5)), Buoyancy.BobbingPeriod(100, 0.5, 1000, 9.81), 15)
    End Sub
End Class
