Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Geometry
    ''' <summary>The distance from a point to a segment, as the protractor, the link picker and the benchmark's overlap measure use it.</summary>
    Public Class DistanceToSegmentTests
        <Theory>
        <InlineData(1.0, 2.0, 2.0)>   ' the foot of the perpendicular lies on the segment
        <InlineData(-3.0, 4.0, 5.0)>  ' beyond the start: to the start (3-4-5)
        <InlineData(7.0, -4.0, 5.0)>  ' beyond the end (4, 0): to the end
        <InlineData(4.0, 0.0, 0.0)>   ' on the end
        Public Sub FromAPoint_ToTheSegmentFromOriginTo4_0(x As Double, y As Double, expected As Double)
            Assert.Equal(expected, Vector.DistanceToSegment(New Vector(x, y), Vector.Zero, New Vector(4, 0)), 12)
        End Sub

        <Fact>
        Public Sub ASegmentOfNoLength_IsItsPoint()
            Assert.Equal(5.0, Vector.DistanceToSegment(New Vector(4, 5), New Vector(1, 1), New Vector(1, 1)), 12)
        End Sub
    End Class
End Namespace
