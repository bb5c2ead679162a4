Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The event solver's collision sequence against a brute-force reference: an event loop written
''' here with no grid, no queue and no stale events, which at every step tries every pair and every
''' wall. If the grid, the cell crossings, the queue or the rule that does not file a pair whose
''' partner collides first ever lose a collision, the two sequences part. (Rounding differs between
''' the two, and a gas amplifies it with every collision, so times agree to 1e-6 s, not to the last digit.)
''' Mixed radii and gravity check that a ball only searching the cells near its own path (the
''' stretch of a straight line or parabola up to its cell's edge) still finds every partner.
''' </summary>
Public Class ReferenceGasTests
    <Theory>
    <InlineData(1, 0.03, 0.0, 0.0, 1.0)>
    <InlineData(2, 0.03, 0.0, 0.0, 1.0)>
    <InlineData(3, 0.015, 0.0, 0.0, 1.0)>
    <InlineData(4, 0.045, 0.0, 0.0, 1.0)>
    <InlineData(5, 0.012, 2.0, 0.0, 1.0)>
    <InlineData(6, 0.012, 2.0, 9.81, 1.0)>
    <InlineData(7, 0.02, 1.0, 30.0, 1.0)>
    <InlineData(8, 0.01, 1.0, 9.81, 2.5)>
    <InlineData(10, 0.01, 1.0, 9.81, 2.5)>
    <InlineData(11, 0.01, 1.0, 9.81, 2.5)>
    <InlineData(12, 0.01, 1.0, 9.81, 2.5)>
    <InlineData(13, 0.01, 1.0, 9.81, 2.5)>
    Public Sub CollisionSequence_MatchesBruteForce(seed As Integer, radius As Double, spread As Double, g As Double, speed As Double)
        Const count = 40
        Const compared = 150
        Dim rng As New Random(seed)
        Dim w As New World(1.0, 1.0, g, 1.0)
        Dim perRow = 7
        For k = 0 To count - 1
            Dim p = New Vector((k Mod perRow + 0.5) / perRow, (k \ perRow + 0.5) / perRow)
            Dim v = New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1) * speed
            ' Radii from radius to (1 + spread) × radius (equal masses, so the reference stays simple).
            Dim r = If(spread > 0, radius * (1 + spread * rng.NextDouble()), radius)
            w.Add(New Circle(p, r, 1.0, v))
        Next
        Dim reference = BruteForceSequence(w, compared)
        Dim seen As New List(Of CollisionRecord)()
        w.CollisionListener = Sub(r) seen.Add(r)
        w.Solver = New EventDrivenSolver()
        While seen.Count < compared
            w.Advance(0.05)
        End While
        Dim index = w.Circles.Select(Function(c, k) (c, k)).ToDictionary(Function(x) x.c, Function(x) x.k)
        For k = 0 To compared - 1
            Dim expected = reference(k)
            Dim actual = seen(k)
            Dim a = index(DirectCast(actual.A, Circle))
            Dim b = If(actual.Kind = CollisionKind.CircleCircle, index(DirectCast(actual.B, Circle)), -1 - CInt(actual.Wall))
            Dim pairOk = (a = expected.A AndAlso b = expected.B) OrElse (a = expected.B AndAlso b = expected.A)
            Assert.True(pairOk, $"collision {k}: solver had {a}–{b} at {actual.Time}, reference {expected.A}–{expected.B} at {expected.Time}")
            Assert.True(Math.Abs(actual.Time - expected.Time) <= 1.0E-6, $"collision {k}: at {actual.Time} s, reference {expected.Time} s")
        Next
    End Sub

    Private Structure Hit
        Friend Time As Double
        Friend A As Integer
        ''' <summary>The other ball, or −1 − wall side.</summary>
        Friend B As Integer
    End Structure

    ''' <summary>The first <paramref name="limit"/> collisions, found by trying everything each time.</summary>
    Private Shared Function BruteForceSequence(w As World, limit As Integer) As List(Of Hit)
        Dim n = w.Circles.Count
        Dim p = w.Circles.Select(Function(c) c.Position).ToArray()
        Dim v = w.Circles.Select(Function(c) c.Velocity).ToArray()
        Dim r = w.Circles.Select(Function(c) c.Radius).ToArray()
        Dim g = w.Gravity
        Dim now = 0.0
        Dim hits As New List(Of Hit)()
        While hits.Count < limit
            Dim best = Double.PositiveInfinity
            Dim hit As Hit
            For i = 0 To n - 1
                For j = i + 1 To n - 1
                    Dim t = PairTime(p(i) - p(j), v(i) - v(j), r(i) + r(j))
                    If t < best Then best = t : hit = New Hit With {.A = i, .B = j}
                Next
                ' Each wall: the gap closes as gap + rate t + ½ accel t² (accel = ∓g for the floor and the ceiling).
                Dim walls = {(WallSide.Left, p(i).X - r(i), v(i).X, 0.0), (WallSide.Right, w.Width - r(i) - p(i).X, -v(i).X, 0.0),
                             (WallSide.Bottom, p(i).Y - r(i), v(i).Y, -g), (WallSide.Top, w.Height - r(i) - p(i).Y, -v(i).Y, g)}
                For Each wall In walls
                    Dim t = GapCloses(wall.Item2, wall.Item3, wall.Item4)
                    If t < best Then best = t : hit = New Hit With {.A = i, .B = -1 - CInt(wall.Item1)}
                Next
            Next
            For i = 0 To n - 1
                p(i) += v(i) * best + New Vector(0, -0.5 * g * best * best)
                v(i) -= New Vector(0, g * best)
            Next
            now += best
            hit.Time = now
            hits.Add(hit)
            If hit.B >= 0 Then
                Dim nrm = (p(hit.A) - p(hit.B)).Normalized(New Vector(0, 1))
                Dim approach = Vector.Dot(v(hit.A) - v(hit.B), nrm)
                v(hit.A) -= nrm * approach ' equal masses, e = 1: the normal components swap
                v(hit.B) += nrm * approach
            Else
                Select Case CType(-1 - hit.B, WallSide)
                    Case WallSide.Left, WallSide.Right : v(hit.A) = New Vector(-v(hit.A).X, v(hit.A).Y)
                    Case Else : v(hit.A) = New Vector(v(hit.A).X, -v(hit.A).Y)
                End Select
            End If
        End While
        Return hits
    End Function

    ''' <summary>When gap + rate t + ½ accel t² first reaches 0 while closing (t ≥ 0), or +∞.</summary>
    Private Shared Function GapCloses(gap As Double, rate As Double, accel As Double) As Double
        If accel = 0 Then Return If(rate < 0, Math.Max(0, -gap / rate), Double.PositiveInfinity)
        If accel < 0 Then Return Math.Max(0, (rate + Math.Sqrt(rate * rate - 2 * accel * gap)) / -accel) ' the floor: always reached
        Dim disc = rate * rate - 2 * accel * gap
        If rate >= 0 OrElse disc < 0 Then Return Double.PositiveInfinity ' the ceiling: reached only if it rises high enough
        Return Math.Max(0, (-rate - Math.Sqrt(disc)) / accel)
    End Function

    ''' <summary>When two balls d apart closing at relative velocity dv first touch (|d + dv t| = R), or +∞.</summary>
    Private Shared Function PairTime(d As Vector, dv As Vector, sumR As Double) As Double
        Dim b = Vector.Dot(d, dv)
        If b >= 0 Then Return Double.PositiveInfinity
        Dim a = Vector.Dot(dv, dv)
        Dim c = Vector.Dot(d, d) - sumR * sumR
        Dim disc = b * b - a * c
        If disc <= 0 Then Return Double.PositiveInfinity
        Return Math.Max(0, c / (-b + Math.Sqrt(disc)))
    End Function
End Class
