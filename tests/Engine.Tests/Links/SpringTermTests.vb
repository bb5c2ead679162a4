Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>The one spring formula every integrated and snapshot motion uses: Hooke's law with damping, along the line of the ends.</summary>
    Public Class SpringTermTests
        Private Shared ReadOnly BallA As New Circle(New Vector(0, 0), 0.1, 2.0)
        Private Shared ReadOnly BallB As New Circle(New Vector(2, 0), 0.1, 4.0)

        <Fact>
        Public Sub AStretchedSpring_PullsEndATowardsB_ByKTimesTheStretch()
            Dim l = Link.CreateSpring(BallA, BallB, stiffness:=10, restLength:=1.5)
            Dim pull = SpringTerm.Pull(l, New Vector(1, 1), Vector.Zero, New Vector(1, 3), Vector.Zero)
            ' d = 2 m, stretch 0.5 m: 5 N along +y, towards B.
            Assert.Equal(0, pull.X, 15)
            Assert.Equal(5.0, pull.Y, 12)
        End Sub

        <Fact>
        Public Sub ACompressedSpring_PushesEndAAwayFromB()
            Dim l = Link.CreateSpring(BallA, BallB, stiffness:=10, restLength:=3)
            Dim pull = SpringTerm.Pull(l, Vector.Zero, Vector.Zero, New Vector(2, 0), Vector.Zero)
            Assert.Equal(-10.0, pull.X, 12)
        End Sub

        <Fact>
        Public Sub Damping_AddsCTimesTheStretchRate_AlongTheLine()
            Dim l = Link.CreateSpring(BallA, BallB, stiffness:=10, restLength:=2, damping:=2)
            ' At its rest length, B moving away at 3 m/s along the line and 7 m/s across it: only the 3 m/s counts, 2 × 3 = 6 N.
            Dim pull = SpringTerm.Pull(l, Vector.Zero, Vector.Zero, New Vector(2, 0), New Vector(3, 7))
            Assert.Equal(6.0, pull.X, 12)
            Assert.Equal(0, pull.Y, 15)
        End Sub

        <Fact>
        Public Sub EndsTogether_GiveNoPull()
            Dim l = Link.CreateSpring(BallA, BallB, stiffness:=10, restLength:=1, damping:=1)
            Assert.Equal(Vector.Zero, SpringTerm.Pull(l, New Vector(1, 1), New Vector(1, 0), New Vector(1, 1), New Vector(0, 1)))
        End Sub

        <Fact>
        Public Sub Add_GivesEachEndItsPullOverItsMass_InOppositeDirections()
            Dim l = Link.CreateSpring(BallA, BallB, stiffness:=10, restLength:=1)
            Dim bodies As Shape() = {BallA, BallB}
            ' States: A at (0, 0), B at (2, 0), both still: 10 N on each, A (2 kg) +5 m/s², B (4 kg) −2.5 m/s².
            Dim y = New Double() {0, 0, 0, 0, 2, 0, 0, 0}
            Dim d(7) As Double
            SpringTerm.Add({l}, bodies, y, d)
            Assert.Equal(5.0, d(2), 12)
            Assert.Equal(-2.5, d(6), 12)
            Assert.Equal(0, d(3), 15)
            Assert.Equal(0, d(7), 15)
        End Sub

        <Fact>
        Public Sub Add_AnAnchoredSpring_PullsItsOneBodyTowardsTheAnchor()
            Dim l = Link.CreateSpring(BallA, New Vector(0, 3), stiffness:=4, restLength:=1)
            Dim y = New Double() {0, 0, 0, 0}
            Dim d(3) As Double
            SpringTerm.Add({l}, New Shape() {BallA}, y, d)
            ' Stretched 2 m: 8 N up on 2 kg.
            Assert.Equal(4.0, d(3), 12)
        End Sub
    End Class
End Namespace
