Option Strict On
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>What a scene file may leave out, and what it means.</summary>
Public Class SceneDefaultsTests
    Private Shared Function Q(json As String) As String
        Return SceneErrorTests.Q(json)
    End Function

    <Fact>
    Public Sub WorldDefaults_AreGravity981_Restitution1_WallsOn()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':3,'height':2},'bodies':[]}"))
        Assert.Equal(3.0, w.Width)
        Assert.Equal(2.0, w.Height)
        Assert.Equal(9.81, w.Gravity)
        Assert.Equal(1.0, w.Restitution)
        Assert.True(w.Walls)
        Assert.Equal(0.0, w.Time)
    End Sub

    <Fact>
    Public Sub BodyDefaults_AreAtRest_Movable_NoColour_IdFromPosition()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':3,'height':2,'gravity':0,'restitution':0.5,'walls':false},'bodies':[" &
            "{'type':'circle','x':1,'y':1,'radius':0.1,'mass':2}," &
            "{'type':'rectangle','x':2,'y':0,'width':0.5,'height':0.2}," &
            "{'type':'circle','x':0.5,'y':1.5,'radius':0.2,'fixed':true}]}"))
        Assert.Equal(0.0, w.Gravity)
        Assert.Equal(0.5, w.Restitution)
        Assert.False(w.Walls)
        Dim c = w.Circles(0)
        Assert.Equal("1", c.Id)
        Assert.Equal(Vector.Zero, c.Velocity)
        Assert.False(c.IsFixed)
        Assert.Equal(2.0, c.Mass)
        Assert.Null(c.Color)
        Assert.Equal("2", w.Rectangles(0).Id)
        Assert.Equal(New Vector(2, 0), w.Rectangles(0).Position)
        Assert.Equal("3", w.Circles(1).Id)
        Assert.True(w.Circles(1).IsFixed)
        Assert.True(Double.IsPositiveInfinity(w.Circles(1).Mass))
    End Sub

    <Fact>
    Public Sub Ids_AreKeptAsGiven_AndMissingOnesArePositions_InFileOrder()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" &
            "{'id':'red','type':'circle','x':1,'y':1,'radius':0.1,'mass':1}," &
            "{'type':'circle','x':2,'y':1,'radius':0.1,'mass':1}," &
            "{'id':'1','type':'circle','x':3,'y':1,'radius':0.1,'mass':1}," &
            "{'id':' ','type':'rectangle','x':4,'y':0,'width':1,'height':0.5}," &
            "{'type':'circle','x':6,'y':1,'radius':0.1,'mass':1,'color':'#A1b2C3'}]}"))
        Assert.Equal("red|2|1| |5", String.Join("|", w.Bodies.Select(Function(b) b.Id)))
        Assert.Equal("#A1b2C3", w.Bodies(4).Color)
    End Sub

    <Fact>
    Public Sub UnknownFields_AreIgnored()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','author':'Ms Smith','world':{'width':8,'height':5,'friction':0.3,'units':{'length':'m'}}," &
            "'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'label':'A','spin':[1,2]}],'notes':null}"))
        Assert.Single(w.Bodies)
    End Sub

    <Fact>
    Public Sub FixedCircle_IgnoresVelocity()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'fixed':true,'vx':3}]}"))
        Assert.Equal(Vector.Zero, w.Circles(0).Velocity)
    End Sub

    <Fact>
    Public Sub TheSpecExample_Loads()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8.0,'height':5.0,'gravity':9.81,'restitution':0.9,'walls':true},'bodies':[" &
            "{ 'id': 'red',   'type': 'circle', 'x': 1.0, 'y': 3.0, 'radius': 0.2, 'mass': 2.0, 'vx': 3.0, 'vy': 0.0 }," &
            "{ 'id': 'peg',   'type': 'circle', 'x': 4.0, 'y': 1.0, 'radius': 0.3, 'fixed': true }," &
            "{ 'id': 'table', 'type': 'rectangle', 'x': 5.0, 'y': 0.0, 'width': 2.0, 'height': 1.2 }]}"))
        Assert.Equal(3, w.Bodies.Count)
        Assert.Equal(New Vector(3, 0), DirectCast(w.Find("red"), Circle).Velocity)
        Assert.Equal(1.2, DirectCast(w.Find("table"), Rectangle).Height)
    End Sub

    <Fact>
    Public Sub ByteOrderMark_AndEscapedText_AreRead()
        Dim w = SceneFile.Load(ChrW(&HFEFF) & "{""format"":""physics-scene\/1"",""world"":{""width"":8,""height"":5},""bodies"":[{""id"":""caf\u00e9 \""x\"""",""type"":""circle"",""x"":1,""y"":1,""radius"":0.1,""mass"":1}]}")
        Assert.Equal("café ""x""", w.Bodies(0).Id)
    End Sub
End Class
