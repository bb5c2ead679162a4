Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The event queue (a calendar queue) against a brute-force minimum: whatever the times (negative,
''' zero, equal, +∞, years of buckets apart, earlier than the current bucket) and however the pace
''' changes, the top is always a body with the earliest time.
''' </summary>
Public Class EventQueueTests
    <Theory>
    <InlineData(1)>
    <InlineData(2)>
    <InlineData(3)>
    <InlineData(4)>
    <InlineData(5)>
    <InlineData(6)>
    <InlineData(13)>
    <InlineData(64)>
    <InlineData(1001)>
    Public Sub Top_IsAlwaysTheEarliest_UnderRandomUpdates(n As Integer)
        Dim rng As New Random(n)
        Dim times = New Double(n - 1) {}
        For i = 0 To n - 1
            times(i) = RandomTime(rng)
        Next
        Dim q As New EventQueue()
        q.Reset(times, n)
        AssertTopIsMinimum(q, times)
        For k = 1 To 3000
            Dim i = rng.Next(n)
            times(i) = RandomTime(rng)
            q.Update(i, times(i))
            AssertTopIsMinimum(q, times)
        Next
    End Sub

    <Fact>
    Public Sub Reset_WithFewerBodiesThanBefore_IgnoresTheOldEntries()
        Dim q As New EventQueue()
        Dim many = {5.0, 4.0, 3.0, 2.0, 1.0, 0.5, 0.25, 0.125}
        q.Reset(many, many.Length)
        Assert.Equal(7, q.Top)
        Dim few = {3.0, 2.0, 9.0}
        q.Reset(few, few.Length)
        Assert.Equal(1, q.Top)
        few(1) = 10.0
        q.Update(1, few(1))
        Assert.Equal(0, q.Top)
    End Sub

    <Fact>
    Public Sub Times_OrderAsNumbers_AcrossSignAndInfinity()
        Dim times = {Double.PositiveInfinity, 1.0E-300, -0.0, -1.0E-300, -2.5, 1.0E+300, -1.0E+300}
        Dim q As New EventQueue()
        q.Reset(times, times.Length)
        Dim order = New List(Of Double)()
        For k = 1 To times.Length
            Dim top = q.Top
            order.Add(times(top))
            times(top) = Double.PositiveInfinity
            q.Update(top, times(top))
        Next
        ' The last one popped was the original +∞; everything before it in increasing order.
        Assert.Equal({-1.0E+300, -2.5, -1.0E-300, -0.0, 1.0E-300, 1.0E+300, Double.PositiveInfinity}, order.ToArray())
    End Sub

    <Theory>
    <InlineData(1, 7)>
    <InlineData(2, 500)>
    <InlineData(3, 3000)>
    Public Sub Top_IsAlwaysTheEarliest_AsTheSolverUsesIt(seed As Integer, n As Integer)
        ' The solver's pattern: the clock moves to the top, which is filed again a little later;
        ' now and then other bodies are filed too (partners, neighbours), some at +∞, some far
        ' ahead (beyond a year of buckets), some at the current instant. Every 20 000 events the
        ' pace changes a thousandfold, so the bucket width is revised both ways on the way.
        Dim rng As New Random(seed)
        Dim times = New Double(n - 1) {}
        For i = 0 To n - 1
            times(i) = rng.NextDouble()
        Next
        Dim q As New EventQueue()
        q.Reset(times, n)
        Dim now = 0.0
        Dim pace = 1.0
        For k = 1 To 100000
            If k Mod 20000 = 0 Then pace = If(pace >= 1, 0.001, 1000.0)
            Dim top = q.Top
            AssertTopIsMinimum(q, times)
            now = times(top)
            times(top) = now + pace * -Math.Log(1 - rng.NextDouble())
            q.Update(top, times(top))
            If rng.Next(3) = 0 Then
                Dim other = rng.Next(n)
                Select Case rng.Next(20)
                    Case 0 : times(other) = Double.PositiveInfinity
                    Case 1 : times(other) = now + pace * 1000 * n
                    Case 2 : times(other) = now
                    Case Else : times(other) = now + pace * rng.NextDouble()
                End Select
                q.Update(other, times(other))
            End If
        Next
    End Sub

    <Fact>
    Public Sub TimesFarApartAndNegative_AreStillTakenInOrder()
        ' Gaps of many years of buckets between the times, and times before the first one filed.
        Dim times = {1.0E+9, 3.0, 2.0E+9, -7.0, 1.0E-9, 5.0E+8, 4.0, Double.PositiveInfinity}
        Dim q As New EventQueue()
        q.Reset(times, times.Length)
        Dim order = New List(Of Double)()
        For k = 1 To times.Length + 1
            Dim top = q.Top
            order.Add(times(top))
            ' When the clock has reached 3 s, the body is filed again at 2.5 s (late): it comes out next.
            times(top) = If(times(top) = 3.0, 2.5, Double.PositiveInfinity)
            q.Update(top, times(top))
        Next
        Assert.Equal({-7.0, 1.0E-9, 3.0, 2.5, 4.0, 5.0E+8, 1.0E+9, 2.0E+9, Double.PositiveInfinity}, order.ToArray())
    End Sub

    Private Shared Function RandomTime(rng As Random) As Double
        Select Case rng.Next(10)
            Case 0 : Return Double.PositiveInfinity
            Case 1 : Return 0.0
            Case 2 : Return -rng.NextDouble() * 100
            Case 3 : Return Math.Floor(rng.NextDouble() * 4) ' many ties
            Case Else : Return rng.NextDouble() * 1000
        End Select
    End Function

    Private Shared Sub AssertTopIsMinimum(q As EventQueue, times As Double())
        Dim minimum = Double.PositiveInfinity
        For Each t In times
            minimum = Math.Min(minimum, t)
        Next
        Dim top = q.Top
        Assert.InRange(top, 0, times.Length - 1)
        Assert.Equal(minimum, times(top))
    End Sub
End Class
