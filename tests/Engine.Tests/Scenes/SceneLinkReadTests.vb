Option Strict On
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>What a scene file's "links" mean once read: ends, ids, and the lengths they leave out.</summary>
Public Class SceneLinkReadTests
    Private Shared Function Q(json As String) As String
        Return SceneErrorTests.Q(json)
    End Function

    Private Shared Function Load(bodies As String, links As String) As World
        Return SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & bodies & "],'links':" & links & "}"))
    End Function

    <Fact>
    Public Sub TheSpecExample_Loads()
        Dim w = Load("{'id':'bob','type':'circle','x':2,'y':1.5,'radius':0.1,'mass':1}," &
                     "{'id':'left','type':'circle','x':4,'y':1,'radius':0.1,'mass':1}," &
                     "{'id':'right','type':'circle','x':4.7,'y':1,'radius':0.1,'mass':1}," &
                     "{'id':'ball1','type':'circle','x':6,'y':3,'radius':0.1,'mass':1}," &
                     "{'id':'ball2','type':'circle','x':7,'y':3,'radius':0.1,'mass':1}",
                     "[{ 'type': 'string', 'a': 'bob', 'at': [2.0, 3.0], 'length': 1.5 }," &
                     " { 'type': 'spring', 'a': 'left', 'b': 'right', 'stiffness': 40, 'rest_length': 0.5 }," &
                     " { 'type': 'rod', 'a': 'ball1', 'b': 'ball2' }]")
        Assert.Equal(3, w.Links.Count)
        Dim pendulum = w.Links(0)
        Assert.Equal(LinkKind.String, pendulum.Kind)
        Assert.Equal("link1", pendulum.Id)
        Assert.Same(w.Find("bob"), pendulum.A)
        Assert.Null(pendulum.B)
        Assert.Equal(New Vector(2, 3), pendulum.Anchor)
        Assert.Equal(1.5, pendulum.Length)
        Dim spring = w.Links(1)
        Assert.Equal(LinkKind.Spring, spring.Kind)
        Assert.Equal("link2", spring.Id)
        Assert.Same(w.Find("left"), spring.A)
        Assert.Same(w.Find("right"), spring.B)
        Assert.Equal(40.0, spring.Stiffness)
        Assert.Equal(0.5, spring.Length)
        Assert.Equal(0.0, spring.Damping)
        ' Stretched from 0.5 m to 0.7 m: it pulls with k·0.2 m = 8 N.
        Assert.Equal(8.0, spring.Tension, 12)
        Dim rod = w.Links(2)
        Assert.Equal(LinkKind.Rod, rod.Kind)
        Assert.Equal("link3", rod.Id)
        Assert.Equal(1.0, rod.Length)
    End Sub

    <Fact>
    Public Sub LeftOutLengths_AreTheDistanceInTheFile_BetweenCircleCentres()
        ' Centres (1, 0.5) and (4, 4.5): a 3-4-5 triangle.
        Dim w = Load("{'id':'p','type':'circle','x':1,'y':0.5,'radius':0.1,'mass':1},{'id':'q','type':'circle','x':4,'y':4.5,'radius':0.1,'mass':1}",
                     "[{'type':'spring','a':'p','b':'q','stiffness':2},{'type':'rod','a':'p','b':'q'},{'type':'string','a':'q','b':'p'}]")
        Assert.Equal(5.0, w.Links(0).Length)
        Assert.Equal(0.0, w.Links(0).Damping)
        Assert.Equal(0.0, w.Links(0).Tension)
        Assert.Equal(5.0, w.Links(1).Length)
        Assert.Equal(5.0, w.Links(2).Length)
        Assert.Equal(New Vector(4, 4.5), w.Links(2).EndA)
        Assert.Equal(New Vector(1, 0.5), w.Links(2).EndB)
    End Sub

    <Fact>
    Public Sub ARectangle_IsJoinedAtItsCentre()
        ' A movable box with its lower-left corner at (4, 0), 1 × 0.5 m: centre (4.5, 0.25). A fixed table
        ' at (6, 0), 1 × 1 m: centre (6.5, 0.5).
        Dim w = Load("{'id':'box','type':'rectangle','x':4,'y':0,'width':1,'height':0.5,'fixed':false,'mass':2}," &
                     "{'id':'table','type':'rectangle','x':6,'y':0,'width':1,'height':1}," &
                     "{'id':'ball','type':'circle','x':6.5,'y':3.5,'radius':0.1,'mass':1}",
                     "[{'type':'rod','a':'box','at':[4.5,3.25]},{'type':'spring','a':'ball','b':'table','stiffness':10}]")
        Assert.Equal(New Vector(4.5, 0.25), w.Links(0).EndA)
        Assert.Equal(3.0, w.Links(0).Length)
        Assert.Equal(New Vector(6.5, 0.5), w.Links(1).EndB)
        Assert.Equal(3.0, w.Links(1).Length)
        Assert.True(w.Links(1).IsAnchored)
    End Sub

    <Fact>
    Public Sub APolygon_IsJoinedAtItsCentroid()
        ' The triangle (1, 0), (2.5, 0), (1, 1.5) has its centroid at the mean of its corners, (1.5, 0.5);
        ' the fixed triangle (6, 3), (7, 3), (6.5, 4) at (6.5, 10/3).
        Dim w = Load("{'id':'tri','type':'polygon','vertices':[[1,0],[2.5,0],[1,1.5]],'mass':1}," &
                     "{'id':'wedge','type':'polygon','vertices':[[6,3],[7,3],[6.5,4]],'fixed':true}",
                     "[{'type':'string','a':'tri','at':[1.5,2.5]},{'type':'rod','a':'tri','b':'wedge'}]")
        Assert.Equal(1.5, w.Links(0).EndA.X, 12)
        Assert.Equal(0.5, w.Links(0).EndA.Y, 12)
        Assert.Equal(2.0, w.Links(0).Length, 12)
        Assert.Equal(6.5, w.Links(1).EndB.X, 12)
        Assert.Equal(10.0 / 3, w.Links(1).EndB.Y, 12)
        Assert.Equal(Vector.Hypot(5, 10.0 / 3 - 0.5), w.Links(1).Length, 12)
    End Sub

    <Fact>
    Public Sub ALeftOutLength_IsExactlyTheBuiltLinksDistance()
        ' Awkward numbers, so a distance measured any other way than the world measures it would show.
        Dim w = Load("{'id':'a','type':'circle','x':0.1,'y':0.30000000000000004,'radius':0.05,'mass':1}," &
                     "{'id':'b','type':'polygon','vertices':[[3.3,1.1],[4.7,1.3],[3.9,2.9]],'mass':1}",
                     "[{'type':'rod','a':'a','b':'b'},{'type':'spring','a':'b','at':[7.77,0.123],'stiffness':3}]")
        Assert.Equal(w.Links(0).Distance, w.Links(0).Length)
        Assert.Equal(w.Links(1).Distance, w.Links(1).Length)
    End Sub

    ''' <summary>"ball" at (2, 2); the point (2, 3.5) is 1.5 m above it.</summary>
    <Theory>
    <InlineData("rod", 1.5)>
    <InlineData("rod", 1.5000000005)>
    <InlineData("rod", 1.4999999995)>
    <InlineData("string", 1.5)>
    <InlineData("string", 1.4999999995)>
    <InlineData("string", 2.0)>
    <InlineData("string", 40.0)>
    Public Sub ALengthThatFitsTheFile_IsKeptAsGiven(type As String, length As Double)
        Dim text = Globalization.CultureInfo.InvariantCulture
        Dim w = Load("{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1}",
                     "[{'type':'" & type & "','a':'ball','at':[2,3.5],'length':" & length.ToString("R", text) & "}]")
        Assert.Equal(length, w.Links(0).Length)
    End Sub

    <Fact>
    Public Sub AStringMayStartSlack_EvenWithItsEndsTogether()
        Dim w = Load("{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1}", "[{'type':'string','a':'ball','at':[2,2],'length':0.7}]")
        Assert.Equal(0.7, w.Links(0).Length)
        Assert.Equal(0.0, w.Links(0).Distance)
    End Sub

    <Fact>
    Public Sub ASpring_MayHaveRestLengthZero_AndItsOwnDamping()
        Dim w = Load("{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1}",
                     "[{'type':'spring','a':'ball','at':[2,2],'stiffness':12.5,'rest_length':0,'damping':0.25},{'type':'spring','a':'ball','at':[2,2],'stiffness':1}]")
        Assert.Equal(0.0, w.Links(0).Length)
        Assert.Equal(12.5, w.Links(0).Stiffness)
        Assert.Equal(0.25, w.Links(0).Damping)
        Assert.Equal(0.0, w.Links(1).Length)
    End Sub

    <Fact>
    Public Sub LinkIds_AreKeptAsGiven_AndMissingOnesAreLinkAndPosition_ApartFromBodyIds()
        Dim w = Load("{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1},{'type':'circle','x':3,'y':2,'radius':0.1,'mass':1}",
                     "[{'id':'ball','type':'rod','a':'ball','at':[2,3]},{'type':'rod','a':'2','at':[3,3]},{'id':'2','type':'rod','a':'ball','b':'2'},{'type':'string','a':'2','at':[3,4]}]")
        Assert.Equal("ball|link2|2|link4", String.Join("|", w.Links.Select(Function(l) l.Id)))
        Assert.Same(w.Find("2"), w.Links(1).A)
        Assert.Same(w.FindLink("2"), w.Links(2))
    End Sub

    <Fact>
    Public Sub UnknownFields_AndFieldsOfNoUseToTheKind_AreIgnored()
        Dim w = Load("{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1}",
                     "[{'type':'rod','a':'ball','at':[2,3],'note':'the pendulum','color':'#ff0000','stiffness':5,'damping':1,'width':{'px':2}}]")
        Assert.Equal(LinkKind.Rod, Assert.Single(w.Links).Kind)
        Assert.Equal(0.0, w.Links(0).Stiffness)
    End Sub

    <Fact>
    Public Sub NoLinks_OrAnEmptyArray_GivesAWorldWithoutLinks()
        Assert.Empty(SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[]}")).Links)
        Assert.Empty(SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[],'links':[]}")).Links)
    End Sub

    <Fact>
    Public Sub ALinkMayAnchorOutsideAWalledContainer()
        Dim w = Load("{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1}", "[{'type':'spring','a':'ball','at':[-3,9],'stiffness':1}]")
        Assert.Equal(New Vector(-3, 9), w.Links(0).Anchor)
        Assert.Equal(Vector.Hypot(5, 7), w.Links(0).Length, 12)
    End Sub
End Class
