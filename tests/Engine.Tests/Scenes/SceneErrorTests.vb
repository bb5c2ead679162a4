Option Strict On
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Every error of scene-format.md, one by one: the reader rejects the file with one line that names
''' the place. JSON is written with ' for " so the cases stay readable.
''' </summary>
Public Class SceneErrorTests
    Private Const Ok As String = "{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[]}"

    ''' <summary>' → ".</summary>
    Friend Shared Function Q(json As String) As String
        Return json.Replace("'"c, """"c)
    End Function

    Private Shared Function Fails(json As String) As SceneFormatException
        Return Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(json))
    End Function

    <Fact>
    Public Sub TheMinimalSceneLoads()
        Dim w = SceneFile.Load(Q(Ok))
        Assert.Equal(8.0, w.Width)
        Assert.Empty(w.Bodies)
    End Sub

    <Theory>
    <InlineData("", "document: is empty, not JSON")>
    <InlineData("   ", "document: is empty, not JSON")>
    <InlineData("[1,2]", "document: must be a JSON object, not an array")>
    <InlineData("'scene'", "document: must be a JSON object, not a string")>
    <InlineData("{'world':{'width':8,'height':5},'bodies':[]}", "format: is required (""physics-scene/1"")")>
    <InlineData("{'format':1,'world':{'width':8,'height':5},'bodies':[]}", "format: must be ""physics-scene/1"", not a number")>
    <InlineData("{'format':'physics-scene/2','world':{'width':8,'height':5},'bodies':[]}", "format: must be ""physics-scene/1"", not ""physics-scene/2""")>
    <InlineData("{'format':'physics-scene/1','bodies':[]}", "world: is required")>
    <InlineData("{'format':'physics-scene/1','world':[],'bodies':[]}", "world: must be an object, not an array")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5}}", "bodies: is required")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':{}}", "bodies: must be an array, not an object")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':null}", "bodies: must be an array, not null")>
    <InlineData("{'format':'physics-scene/1','format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[]}", "format: appears more than once")>
    Public Sub Document_Errors(json As String, expected As String)
        Dim ex = Fails(Q(json))
        Assert.Equal(expected, ex.Message)
    End Sub

    <Theory>
    <InlineData("{'format':'physics-scene/1',")>
    <InlineData("not json at all")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8 'height':5},'bodies':[]}")>
    <InlineData("{format:'physics-scene/1'}")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[]}}")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[]}{}")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[]} x")>
    Public Sub NotJson_IsRejectedInOneLine(json As String)
        Dim ex = Fails(Q(json))
        Assert.StartsWith("document: is not valid JSON (", ex.Message)
        Assert.Equal("document", ex.Place)
        Assert.DoesNotContain(vbLf, ex.Message)
        Assert.DoesNotContain(vbCr, ex.Message)
    End Sub

    <Theory>
    <InlineData("{'height':5}", "world.width: is required")>
    <InlineData("{'width':8}", "world.height: is required")>
    <InlineData("{'width':0,'height':5}", "world.width: must be greater than 0")>
    <InlineData("{'width':-8,'height':5}", "world.width: must be greater than 0")>
    <InlineData("{'width':8,'height':-0.0}", "world.height: must be greater than 0")>
    <InlineData("{'width':'8','height':5}", "world.width: must be a number, not a string")>
    <InlineData("{'width':8,'height':null}", "world.height: must be a number, not null")>
    <InlineData("{'width':8,'height':[5]}", "world.height: must be a number, not an array")>
    <InlineData("{'width':8,'height':5,'gravity':-9.81}", "world.gravity: must be 0 or greater")>
    <InlineData("{'width':8,'height':5,'gravity':true}", "world.gravity: must be a number, not true")>
    <InlineData("{'width':8,'height':5,'restitution':1.5}", "world.restitution: must be between 0 and 1")>
    <InlineData("{'width':8,'height':5,'restitution':-0.1}", "world.restitution: must be between 0 and 1")>
    <InlineData("{'width':8,'height':5,'restitution':{}}", "world.restitution: must be a number, not an object")>
    <InlineData("{'width':8,'height':5,'walls':'yes'}", "world.walls: must be true or false, not a string")>
    <InlineData("{'width':8,'height':5,'walls':1}", "world.walls: must be true or false, not a number")>
    <InlineData("{'width':1e400,'height':5}", "world.width: must be a finite number (1e400 is too large)")>
    <InlineData("{'width':8,'height':-1e400}", "world.height: must be a finite number (-1e400 is too large)")>
    <InlineData("{'width':NaN,'height':5}", "world.width: must be a finite number, not NaN")>
    <InlineData("{'width':8,'height':5,'gravity':Infinity}", "world.gravity: must be a finite number, not Infinity")>
    <InlineData("{'width':-Infinity,'height':5}", "world.width: must be a finite number, not -Infinity")>
    <InlineData("{'width':0x10,'height':5}", "world.width: is not a valid JSON number: 0x10")>
    <InlineData("{'width':08,'height':5}", "world.width: is not a valid JSON number: 08")>
    <InlineData("{'width':8.,'height':5}", "world.width: is not a valid JSON number: 8.")>
    <InlineData("{'width':8,'width':9,'height':5}", "world.width: appears more than once")>
    Public Sub World_Errors(world As String, expected As String)
        Dim ex = Fails(Q("{'format':'physics-scene/1','world':" & world & ",'bodies':[]}"))
        Assert.Equal(expected, ex.Message)
    End Sub

    <Theory>
    <InlineData("[1]", "bodies[0]: must be an object, not a number")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},[]]", "bodies[1]: must be an object, not an array")>
    <InlineData("[{'x':1,'y':1,'radius':0.1,'mass':1}]", "bodies[0].type: is required")>
    <InlineData("[{'type':'triangle','x':1,'y':1}]", "bodies[0].type: unknown type ""triangle"" (expected ""circle"", ""rectangle"", ""segment"", ""polygon"" or ""liquid"")")>
    <InlineData("[{'type':'Circle','x':1,'y':1,'radius':0.1,'mass':1}]", "bodies[0].type: unknown type ""Circle"" (expected ""circle"", ""rectangle"", ""segment"", ""polygon"" or ""liquid"")")>
    <InlineData("[{'type':3,'x':1,'y':1}]", "bodies[0].type: must be a string, not a number")>
    <InlineData("[{'type':'circle','y':1,'radius':0.1,'mass':1}]", "bodies[0].x: is required")>
    <InlineData("[{'type':'circle','x':1,'radius':0.1,'mass':1}]", "bodies[0].y: is required")>
    <InlineData("[{'type':'circle','x':1,'y':'1','radius':0.1,'mass':1}]", "bodies[0].y: must be a number, not a string")>
    <InlineData("[{'type':'circle','x':1,'y':1,'mass':1}]", "bodies[0].radius: is required")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':2,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':3,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':4,'y':1,'radius':0,'mass':1}]", "bodies[3].radius: must be greater than 0")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':-0.1,'mass':1}]", "bodies[0].radius: must be greater than 0")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1}]", "bodies[0].mass: is required")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':-2}]", "bodies[0].mass: must be greater than 0")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':0}]", "bodies[0].mass: must be greater than 0")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'fixed':false}]", Nothing)>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'fixed':true,'mass':-1}]", "bodies[0].mass: must be greater than 0")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'vx':'fast'}]", "bodies[0].vx: must be a number, not a string")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'vy':1e400}]", "bodies[0].vy: must be a finite number (1e400 is too large)")>
    <InlineData("[{'type':'circle','x':NaN,'y':1,'radius':0.1,'mass':1}]", "bodies[0].x: must be a finite number, not NaN")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'fixed':'yes'}]", "bodies[0].fixed: must be true or false, not a string")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'color':'red'}]", "bodies[0].color: must be a colour ""#rrggbb"" such as ""#e53935"", not ""red""")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'color':'#12345'}]", "bodies[0].color: must be a colour ""#rrggbb"" such as ""#e53935"", not ""#12345""")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'color':'#12345g'}]", "bodies[0].color: must be a colour ""#rrggbb"" such as ""#e53935"", not ""#12345g""")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'color':255}]", "bodies[0].color: must be a string, not a number")>
    <InlineData("[{'type':'rectangle','x':1,'y':1,'width':0,'height':1}]", "bodies[0].width: must be greater than 0")>
    <InlineData("[{'type':'rectangle','x':1,'y':1,'width':1}]", "bodies[0].height: is required")>
    <InlineData("[{'type':'rectangle','x':1,'y':1,'width':1,'height':-1}]", "bodies[0].height: must be greater than 0")>
    <InlineData("[{'type':'rectangle','y':1,'width':1,'height':1}]", "bodies[0].x: is required")>
    <InlineData("[{'type':'rectangle','x':1,'y':1,'width':1,'height':1,'color':'#GGGGGG'}]", "bodies[0].color: must be a colour ""#rrggbb"" such as ""#e53935"", not ""#GGGGGG""")>
    <InlineData("[{'type':'circle','id':'','x':1,'y':1,'radius':0.1,'mass':1}]", "bodies[0].id: must not be empty")>
    <InlineData("[{'type':'circle','id':7,'x':1,'y':1,'radius':0.1,'mass':1}]", "bodies[0].id: must be a string, not a number")>
    <InlineData("[{'type':'circle','id':'a','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','id':'a','x':2,'y':1,'radius':0.1,'mass':1}]", "bodies[1].id: ""a"" is already the id of bodies[0]")>
    <InlineData("[{'type':'circle','id':'2','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':2,'y':1,'radius':0.1,'mass':1}]", "bodies[1]: has no id, so it is named ""2"" by its position, but bodies[0] already has that id")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'rectangle','id':'1','x':2,'y':1,'width':1,'height':1}]", "bodies[1].id: ""1"" is already the id of bodies[0]")>
    <InlineData("[{'type':'circle','x':1,'y':1,'radius':0.1,'radius':0.2,'mass':1}]", "bodies[0].radius: appears more than once")>
    Public Sub Body_Errors(bodies As String, expected As String)
        Dim json = Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':" & bodies & "}")
        If expected Is Nothing Then
            Assert.Single(SceneFile.Load(json).Bodies)
        Else
            Assert.Equal(expected, Fails(json).Message)
        End If
    End Sub

    <Theory>
    <InlineData("{'type':'circle','x':0.05,'y':1,'radius':0.1,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out on the left (x - radius = -0.05 m < 0)")>
    <InlineData("{'type':'circle','x':7.95,'y':1,'radius':0.1,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out on the right (x + radius = 8.05 m > width = 8 m)")>
    <InlineData("{'type':'circle','x':1,'y':0.05,'radius':0.1,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out at the bottom (y - radius = -0.05 m < 0)")>
    <InlineData("{'type':'circle','x':1,'y':4.95,'radius':0.1,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out at the top (y + radius = 5.05 m > height = 5 m)")>
    <InlineData("{'type':'circle','x':-20,'y':1,'radius':0.1,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out on the left (x - radius = -20.1 m < 0)")>
    <InlineData("{'type':'circle','x':4,'y':2.5,'radius':3,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out at the bottom (y - radius = -0.5 m < 0)")>
    Public Sub MovableCircleOutsideAWalledContainer_IsAnError(body As String, expected As String)
        Dim json = Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & body & "]}")
        Dim ex = Fails(json)
        Assert.Equal("bodies[0]", ex.Place)
        Assert.Equal(expected, ex.Message)
    End Sub

    <Theory>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1.1,'y':1,'radius':0.1,'mass':1}", "bodies[1]: overlaps bodies[0] by 0.1 m")>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':5,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1,'y':1.15,'radius':0.1,'mass':1}", "bodies[2]: overlaps bodies[0] by 0.05 m")>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'fixed':true},{'type':'circle','x':1.1,'y':1,'radius':0.1,'mass':1}", "bodies[1]: overlaps bodies[0] by 0.1 m")>
    <InlineData("{'type':'rectangle','x':2,'y':0,'width':2,'height':1},{'type':'circle','x':3,'y':1.05,'radius':0.1,'mass':1}", "bodies[1]: overlaps bodies[0] by 0.05 m")>
    <InlineData("{'type':'circle','x':3,'y':1.05,'radius':0.1,'mass':1},{'type':'rectangle','x':2,'y':0,'width':2,'height':1}", "bodies[1]: overlaps bodies[0] by 0.05 m")>
    <InlineData("{'type':'rectangle','x':2,'y':0,'width':2,'height':1},{'type':'circle','x':3,'y':0.9,'radius':0.1,'mass':1}", "bodies[1]: overlaps bodies[0] by 0.2 m")>
    <InlineData("{'type':'rectangle','x':2,'y':0,'width':2,'height':1},{'type':'circle','x':4.05,'y':1.05,'radius':0.1,'mass':1}", "bodies[1]: overlaps bodies[0] by 0.0292893 m")>
    <InlineData("{'type':'rectangle','x':0,'y':0,'width':8,'height':0.5},{'type':'circle','x':1,'y':2,'radius':0.1,'mass':1},{'type':'circle','x':7,'y':0.55,'radius':0.1,'mass':1}", "bodies[2]: overlaps bodies[0] by 0.05 m")>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1.2,'y':1,'radius':0.1000000011,'mass':1}", "bodies[1]: overlaps bodies[0] by 1.1e-09 m")>
    Public Sub Overlaps_AreErrors_NamingBothBodies(bodies As String, expected As String)
        Dim json = Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & bodies & "]}")
        Dim ex = Fails(json)
        Assert.Equal(expected.Replace("1.1e-09", "1.1E-09"), ex.Message)
    End Sub

    <Theory>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1.2,'y':1,'radius':0.1,'mass':1}")>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1.2,'y':1,'radius':0.1000000005,'mass':1}")>
    <InlineData("{'type':'rectangle','x':2,'y':0,'width':2,'height':1},{'type':'circle','x':3,'y':1.1,'radius':0.1,'mass':1}")>
    <InlineData("{'type':'rectangle','x':2,'y':0,'width':2,'height':1},{'type':'circle','x':3,'y':1,'radius':0.3,'fixed':true}")>
    <InlineData("{'type':'rectangle','x':2,'y':0,'width':2,'height':1},{'type':'rectangle','x':3,'y':0.5,'width':2,'height':1}")>
    <InlineData("{'type':'rectangle','x':-1,'y':-1,'width':10,'height':0.5},{'type':'circle','x':-3,'y':9,'radius':1,'fixed':true}")>
    <InlineData("{'type':'circle','x':0.1,'y':0.1,'radius':0.1,'mass':1},{'type':'circle','x':7.9,'y':4.9,'radius':0.1,'mass':1}")>
    <InlineData("{'type':'circle','x':0.2,'y':0.1,'radius':0.1,'mass':1},{'type':'circle','x':0.1,'y':0.30000000000000004,'radius':0.1,'mass':1}")>
    <InlineData("{'type':'circle','x':1,'y':1,'radius':0.1,'fixed':true},{'type':'circle','x':1.1,'y':1,'radius':0.1,'fixed':true}")>
    <InlineData("{'type':'segment','x1':0,'y1':0,'x2':3,'y2':3},{'type':'rectangle','x':1,'y':1,'width':1,'height':1}")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[1.5,2]],'fixed':true},{'type':'circle','x':1.5,'y':1.2,'radius':0.5,'fixed':true}")>
    <InlineData("{'type':'segment','x1':0,'y1':1,'x2':4,'y2':1},{'type':'rectangle','x':1,'y':1,'width':1,'height':1,'fixed':false,'mass':2}")>
    <InlineData("{'type':'rectangle','x':1,'y':0,'width':1,'height':1,'fixed':false,'mass':2},{'type':'rectangle','x':2,'y':0,'width':1,'height':1,'fixed':false,'mass':2}")>
    Public Sub TouchingFixedOverlapsAndFixedOutside_AreAllowed(bodies As String)
        Dim json = Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & bodies & "]}")
        Assert.Equal(2, SceneFile.Load(json).Bodies.Count)
    End Sub

    <Theory>
    <InlineData("{'type':'segment','x1':1,'y1':1,'x2':1,'y2':1}", "bodies[0]: a segment's two ends must differ (both are at x = 1, y = 1)")>
    <InlineData("{'type':'segment','y1':1,'x2':2,'y2':1}", "bodies[0].x1: is required")>
    <InlineData("{'type':'segment','x1':1,'y1':1,'x2':2}", "bodies[0].y2: is required")>
    <InlineData("{'type':'segment','x1':1,'y1':1,'x2':'2','y2':1}", "bodies[0].x2: must be a number, not a string")>
    <InlineData("{'type':'polygon','mass':1}", "bodies[0].vertices: is required")>
    <InlineData("{'type':'polygon','vertices':{},'mass':1}", "bodies[0].vertices: must be an array of [x, y] pairs, not an object")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1]],'mass':1}", "bodies[0].vertices: a polygon needs at least 3 corners, not 2")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],3],'mass':1}", "bodies[0].vertices[2]: must be an [x, y] pair, not a number")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[3]],'mass':1}", "bodies[0].vertices[2]: must be an [x, y] pair, not 1 numbers")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[3,'a']],'mass':1}", "bodies[0].vertices[2][1]: must be a number, not a string")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[3,NaN]],'mass':1}", "bodies[0].vertices[2][1]: must be a finite number, not NaN")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[3,1]],'mass':1}", "bodies[0].vertices: the polygon has zero area")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[3,1],[2,1.5],[3,3],[1,3]],'mass':1}", "bodies[0].vertices: the polygon is not convex (its corners must go round it once, turning the same way at every corner)")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[1,1],[1,1]],'mass':1}", "bodies[0].vertices: a polygon needs at least 3 distinct corners")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[1,2]]}", "bodies[0].mass: is required")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[1,2]],'mass':0}", "bodies[0].mass: must be greater than 0")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[2,1],[1,2]],'fixed':'no'}", "bodies[0].fixed: must be true or false, not a string")>
    <InlineData("{'type':'rectangle','x':1,'y':1,'width':1,'height':1,'fixed':false}", "bodies[0].mass: is required")>
    <InlineData("{'type':'rectangle','x':1,'y':1,'width':1,'height':1,'fixed':false,'mass':-1}", "bodies[0].mass: must be greater than 0")>
    <InlineData("{'type':'rectangle','x':1,'y':1,'width':1,'height':1,'fixed':false,'mass':1,'vx':'x'}", "bodies[0].vx: must be a number, not a string")>
    Public Sub NewBodyKinds_Errors(body As String, expected As String)
        Dim ex = Fails(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & body & "]}"))
        Assert.Equal(expected, ex.Message)
    End Sub

    <Theory>
    <InlineData("{'type':'rectangle','x':-0.5,'y':1,'width':1,'height':1,'fixed':false,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out on the left (its left side is at x = -0.5 m < 0)")>
    <InlineData("{'type':'polygon','vertices':[[7,1],[8.5,1],[7,2]],'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out on the right (its right side is at x = 8.5 m > width = 8 m)")>
    <InlineData("{'type':'polygon','vertices':[[1,-1],[2,1],[1,2]],'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out at the bottom (its bottom is at y = -1 m < 0)")>
    <InlineData("{'type':'rectangle','x':1,'y':4.5,'width':1,'height':1,'fixed':false,'mass':1}", "bodies[0]: is not wholly inside the container: it sticks out at the top (its top is at y = 5.5 m > height = 5 m)")>
    Public Sub MovableBoxOrPolygonOutsideAWalledContainer_IsAnError(body As String, expected As String)
        Dim ex = Fails(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & body & "]}"))
        Assert.Equal("bodies[0]", ex.Place)
        Assert.Equal(expected, ex.Message)
    End Sub

    <Theory>
    <InlineData("{'type':'segment','x1':0,'y1':1,'x2':4,'y2':1},{'type':'circle','x':2,'y':1.05,'radius':0.1,'mass':1}", "bodies[1]: overlaps bodies[0] by 0.05 m")>
    <InlineData("{'type':'rectangle','x':1,'y':0,'width':1,'height':1},{'type':'rectangle','x':1.5,'y':0.75,'width':1,'height':1,'fixed':false,'mass':2}", "bodies[1]: overlaps bodies[0] by 0.25 m")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[3,1],[2,2]],'mass':1},{'type':'circle','x':2,'y':0.95,'radius':0.1,'fixed':true}", "bodies[1]: overlaps bodies[0] by 0.05 m")>
    <InlineData("{'type':'polygon','vertices':[[1,1],[3,1],[2,2]],'mass':1},{'type':'polygon','vertices':[[1.5,0.5],[2.5,0.5],[2,1.2]],'mass':1}", "bodies[1]: overlaps bodies[0] by 0.2 m")>
    Public Sub NewBodyKinds_Overlaps_AreErrors(bodies As String, expected As String)
        Dim ex = Fails(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" & bodies & "]}"))
        Assert.Equal(expected, ex.Message)
    End Sub

    <Fact>
    Public Sub NewBodyKinds_Load_WithTheirDefaults()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" &
            "{'id':'ramp','type':'segment','x1':0,'y1':2,'x2':3,'y2':0.5}," &
            "{'id':'box','type':'rectangle','x':4,'y':0,'width':1,'height':0.5,'fixed':false,'mass':3,'vx':2}," &
            "{'id':'table','type':'rectangle','x':6,'y':0,'width':1,'height':1}," &
            "{'id':'tri','type':'polygon','vertices':[[1,3],[1,4],[2,3]],'mass':1.5}," &
            "{'id':'wedge','type':'polygon','vertices':[[5,3],[6,3],[5.5,4]],'fixed':true}]}"))
        Assert.Equal(5, w.Bodies.Count)
        Dim ramp = DirectCast(w.Find("ramp"), Segment)
        Assert.True(ramp.IsFixed)
        Assert.Equal(New Vector(3, 0.5), ramp.EndPoint)
        Dim box = DirectCast(w.Find("box"), Rectangle)
        Assert.False(box.IsFixed)
        Assert.Equal(3.0, box.Mass)
        Assert.Equal(New Vector(2, 0), box.Velocity)
        Assert.True(w.Find("table").IsFixed)
        Dim tri = DirectCast(w.Find("tri"), Polygon)
        Assert.False(tri.IsFixed)
        Assert.Equal(4.0 / 3, tri.Position.X, 12)
        Assert.Equal(10.0 / 3, tri.Position.Y, 12)
        Assert.True(w.Find("wedge").IsFixed)
        Assert.Equal("box,tri", String.Join(",", w.Movables.Select(Function(b) b.Id)))
    End Sub

    <Fact>
    Public Sub WithoutWalls_AMovableCircleMayStartOutside()
        Dim w = SceneFile.Load(Q("{'format':'physics-scene/1','world':{'width':8,'height':5,'walls':false},'bodies':[{'type':'circle','x':-3,'y':9,'radius':0.1,'mass':1}]}"))
        Assert.Equal(New Vector(-3, 9), w.Circles(0).Position)
    End Sub

    <Fact>
    Public Sub ErrorsCarryPlaceAndProblem()
        Dim ex = Fails(Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0,'mass':1}]}"))
        Assert.Equal("bodies[0].radius", ex.Place)
        Assert.Equal("must be greater than 0", ex.Problem)
    End Sub
End Class
