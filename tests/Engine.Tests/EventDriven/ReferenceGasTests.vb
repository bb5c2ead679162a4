Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The event solver's collision sequence against a brute-force reference: an event loop written
''' here with no grid, no queue and no stale events, which at every step tries every pair and every
''' wall. If the grid, the cell crossings, the queue or the rule that does not file a pair whose
''' partner collides first ever lose a collision, the two sequences part. (Rounding differs between
''' the two, and a gas amplifies it with every collision, so times agree to 1e-6 s, not to the last digit.)
''' </summary>
Public Class ReferenceGasTests
    <Theory>
    <InlineData(1, 0.03)>
    <InlineData(2, 0.03)>
    <InlineData(3, 0.015)>
    <InlineData(4, 0.045)>
    Public Sub CollisionSequence_MatchesBruteForce(seed As Integer, radius As Double)
        Const count = 40
        Const compared = 150
        Dim rng As New Random(seed)
        Dim w As New World(1.0, 1.0, 0.0, 1.0)
        Dim perRow = 7
        For k = 0 To count - 1
            Dim p = New Vector((k Mod perRow + 0.5) / perRow, (k \ perRow + 0.5) / perRow)
            Dim v = New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1)
            w.Add(New Circle(p, radius, 1.0, v))
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
            Dim a = index(actual.A)
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
                Dim walls = {(WallSide.Left, p(i).X - r(i), v(i).X), (WallSide.Right, w.Width - r(i) - p(i).X, -v(i).X),
                             (WallSide.Bottom, p(i).Y - r(i), v(i).Y), (WallSide.Top, w.Height - r(i) - p(i).Y, -v(i).Y)}
                For Each wall In walls
                    If wall.Item3 < 0 Then
                        Dim t = Math.Max(0, -wall.Item2 / wall.Item3)
                        If t < best Then best = t : hit = New Hit With {.A = i, .B = -1 - CInt(wall.Item1)}
                    End If
                Next
            Next
            For i = 0 To n - 1
                p(i) += v(i) * best
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
