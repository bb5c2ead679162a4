Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Response
    ''' <summary><see cref="ContactCluster.Resolve"/> at its boundary: bad input, empty input, and its solve cap.</summary>
    Public Class ContactClusterInputTests
        Private Shared ReadOnly Floor As New ClusterContact(0, ClusterContact.World, New Vector(0, 1))

        <Fact>
        Public Sub BadInput_IsRejectedWithAMessageThatNamesIt()
            Dim one = {New Vector(0, -1)}
            AssertRejected("velocities", Function() ContactCluster.Resolve(Listed(1.0, 1.0), one, Listed(Floor), 0.5))
            AssertRejected("restitution", Function() ContactCluster.Resolve(Listed(1.0), one, Listed(Floor), 1.5))
            AssertRejected("restitution", Function() ContactCluster.Resolve(Listed(1.0), one, Listed(Floor), Double.NaN))
            AssertRejected("inverseMasses(0)", Function() ContactCluster.Resolve(Listed(-1.0), one, Listed(Floor), 0.5))
            AssertRejected("inverseMasses(0)", Function() ContactCluster.Resolve(Listed(Double.PositiveInfinity), one, Listed(Floor), 0.5))
            AssertRejected("velocities(0)", Function() ContactCluster.Resolve(Listed(1.0), Listed(New Vector(Double.NaN, 0)), Listed(Floor), 0.5))
            AssertRejected("contacts(0).BodyA", Function() ContactCluster.Resolve(Listed(1.0), one, Listed(New ClusterContact(1, ClusterContact.World, New Vector(0, 1))), 0.5))
            AssertRejected("contacts(0).BodyB", Function() ContactCluster.Resolve(Listed(1.0), one, Listed(New ClusterContact(0, 3, New Vector(0, 1))), 0.5))
            AssertRejected("itself", Function() ContactCluster.Resolve(Listed(1.0, 1.0), Listed(one(0), one(0)), Listed(New ClusterContact(1, 1, New Vector(0, 1))), 0.5))
            AssertRejected("contacts(0).Normal", Function() ContactCluster.Resolve(Listed(1.0), one, Listed(New ClusterContact(0, ClusterContact.World, New Vector(0, 2))), 0.5))
            Assert.Throws(Of ArgumentNullException)(Function() ContactCluster.Resolve(Nothing, one, Listed(Floor), 0.5))
        End Sub

        <Fact>
        Public Sub NoContacts_OrNothingMoving_LeavesEverythingAsItWas()
            Dim v = {New Vector(1, 2), New Vector(-3, 0)}
            Dim none = ContactCluster.Resolve(Listed(1.0, 2.0), v, Array.Empty(Of ClusterContact)(), 0.5)
            Assert.Equal(v, none.Velocities)
            Assert.True(none.Separated)
            Dim still = ContactCluster.Resolve(Listed(1.0), Listed(Vector.Zero), Listed(Floor), 0.5)
            Assert.Equal(Vector.Zero, still.Velocities(0))
            Assert.Equal(0.0, still.Impulses(0))
        End Sub

        <Fact>
        Public Sub AtTheSolveCap_ReturnsTheLastAcceptedPoint_AndSaysItIsNotSeparated()
            ' Three equal balls in a row, the left one moving right at 1 m/s, need two solves (one per contact).
            ' Allowed only one, the method has resolved the first pair perfectly inelastically, (½, ½, 0), and
            ' stops there: restitution is skipped (its energy argument needs the finished compression), every
            ' impulse is ≥ 0, momentum is kept, and the second contact is reported as still approaching.
            Dim left = New Vector(-1, 0)
            Dim inverse = {1.0, 1.0, 1.0}
            Dim before = {New Vector(1, 0), Vector.Zero, Vector.Zero}
            Dim contacts = {New ClusterContact(0, 1, left), New ClusterContact(1, 2, left)}
            Dim workspace As New ContactClusterWorkspace()
            workspace.Projection.SolveCapOverride = 1
            Dim result = ContactCluster.Resolve(inverse, before, contacts, 1.0, workspace)
            Assert.False(result.Separated)
            Assert.Equal(0.5, result.Velocities(0).X, 15)
            Assert.Equal(0.5, result.Velocities(1).X, 15)
            Assert.Equal(0.0, result.Velocities(2).X)
            Assert.Equal(0.5, result.Impulses(0), 15)
            Assert.Equal(0.0, result.Impulses(1))

            ' The same workspace with the normal cap finishes the job.
            workspace.Projection.SolveCapOverride = 0
            Assert.True(ContactCluster.Resolve(inverse, before, contacts, 1.0, workspace).Separated)
        End Sub

        Private Shared Sub AssertRejected(named As String, act As Func(Of ClusterResolution))
            Dim ex = Assert.ThrowsAny(Of ArgumentException)(Function() act())
            Assert.Contains(named, ex.Message, StringComparison.Ordinal)
        End Sub
    End Class
End Namespace
