Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The bound a corner slide uses to skip far bodies (<see cref="CornerSlides.EarliestEntry"/>): never
''' later than the exact time a body enters the disc, or a skipped body could have been the next event.
''' </summary>
Public Class SlideReachBoundTests
    <Fact>
    Public Sub EarliestEntry_IsNeverAfterTheExactEntry_ForRandomMotions()
        Dim random = New Random(20261124)
        Dim entered = 0
        For trial = 1 To 20000
            Dim reach = 0.01 + 0.1 * random.NextDouble() ' m
            Dim distance = reach * (0.5 + 20 * random.NextDouble()) ' m from the disc's centre
            Dim angle = 2 * Math.PI * random.NextDouble()
            Dim dx = distance * Math.Cos(angle), dy = distance * Math.Sin(angle)
            Dim speed = 5 * random.NextDouble() ' m/s
            Dim heading = 2 * Math.PI * random.NextDouble()
            Dim vx = speed * Math.Cos(heading), vy = speed * Math.Sin(heading)
            ' Free fall, or a slide along a slope (gravity's part along it), or none.
            Dim ay = If(trial Mod 3 = 0, 0.0, -9.81 * random.NextDouble())
            Dim ax = If(trial Mod 3 = 1, 9.81 * (random.NextDouble() - 0.5), 0.0)
            Dim slop = 1.0E-12 * Math.Max(1.0, distance)
            Dim exact = TimeOfImpact.CircleCircleAccelerated(dx, dy, vx, vy, ax, ay, reach, slop)
            Dim bound = CornerSlides.EarliestEntry(dx, dy, vx, vy, ax, ay, reach, slop)
            Assert.True(bound >= 0, $"trial {trial}: bound {bound} s is negative")
            If exact < Double.PositiveInfinity Then
                entered += 1
                Assert.True(bound <= exact, $"trial {trial}: bound {bound} s is after the entry at {exact} s")
            End If
        Next
        Assert.True(entered > 1000, $"only {entered} trials entered the disc")
    End Sub

    <Fact>
    Public Sub EarliestEntry_HeadOnWithoutAcceleration_IsTheStraightLineTime()
        ' 1 m from a 0.1 m disc at 2 m/s straight at it: it arrives after (1 − 0.1) / 2 = 0.45 s.
        Dim bound = CornerSlides.EarliestEntry(1.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.1, 1.0E-12)
        Assert.Equal(0.45, bound, 5)
    End Sub

    <Fact>
    Public Sub EarliestEntry_AtRestOutside_IsNever_AndInside_IsNow()
        Assert.Equal(Double.PositiveInfinity, CornerSlides.EarliestEntry(1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.1, 1.0E-12))
        Assert.Equal(0.0, CornerSlides.EarliestEntry(0.05, 0.0, 1.0, 0.0, 0.0, -9.81, 0.1, 1.0E-12))
    End Sub
End Class
