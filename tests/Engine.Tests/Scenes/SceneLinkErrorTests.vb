Option Strict On
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Every error a scene file's "links" can hold, one by one: the reader rejects the file with one line that
''' names the place, as it does for bodies. JSON is written with ' for " so the cases stay readable.
''' </summary>
Public Class SceneLinkErrorTests
    ''' <summary>
    ''' bodies[0] "ball" (movable circle at 2, 2), bodies[1] "ball2" (movable circle at 3, 2), bodies[2] "peg"
    ''' (fixed circle at 5, 4), bodies[3] "table" (fixed rectangle, centre 6.5, 0.5), bodies[4] "ramp" (segment),
    ''' bodies[5] "box" (movable box, centre 4.5, 0.25).
    ''' </summary>
    Private Const Bodies As String = "[" &
        "{'id':'ball','type':'circle','x':2,'y':2,'radius':0.1,'mass':1}," &
        "{'id':'ball2','type':'circle','x':3,'y':2,'radius':0.1,'mass':1}," &
        "{'id':'peg','type':'circle','x':5,'y':4,'radius':0.1,'fixed':true}," &
        "{'id':'table','type':'rectangle','x':6,'y':0,'width':1,'height':1}," &
        "{'id':'ramp','type':'segment','x1':0,'y1':4,'x2':1,'y2':4.5}," &
        "{'id':'box','type':'rectangle','x':4,'y':0,'width':1,'height':0.5,'fixed':false,'mass':2}]"

    Friend Shared Function Scene(links As String) As String
        Return SceneErrorTests.Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':" & Bodies & ",'links':" & links & "}")
    End Function

    Private Shared Function Fails(links As String) As SceneFormatException
        Return Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(Scene(links)))
    End Function

    <Theory>
    <InlineData("{}", "links: must be an array, not an object")>
    <InlineData("null", "links: must be an array, not null")>
    <InlineData("'rod'", "links: must be an array, not a string")>
    <InlineData("[1]", "links[0]: must be an object, not a number")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3]},[]]", "links[1]: must be an object, not an array")>
    Public Sub TheLinksArray_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'a':'ball','at':[2,3]}]", "links[0].type: is required")>
    <InlineData("[{'type':2,'a':'ball','at':[2,3]}]", "links[0].type: must be a string, not a number")>
    <InlineData("[{'type':'elastic','a':'ball','at':[2,3]}]", "links[0].type: unknown type ""elastic"" (expected ""spring"", ""rod"" or ""string"")")>
    <InlineData("[{'type':'Rod','a':'ball','at':[2,3]}]", "links[0].type: unknown type ""Rod"" (expected ""spring"", ""rod"" or ""string"")")>
    <InlineData("[{'type':'rod','type':'rod','a':'ball','at':[2,3]}]", "links[0].type: appears more than once")>
    Public Sub Type_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'id':'','type':'rod','a':'ball','at':[2,3]}]", "links[0].id: must not be empty")>
    <InlineData("[{'id':3,'type':'rod','a':'ball','at':[2,3]}]", "links[0].id: must be a string, not a number")>
    <InlineData("[{'id':'s','type':'rod','a':'ball','at':[2,3]},{'id':'t','type':'rod','a':'ball2','at':[3,3]},{'id':'s','type':'rod','a':'box','at':[4.5,3]}]", "links[2].id: ""s"" is already the id of links[0]")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3]},{'id':'link1','type':'rod','a':'ball2','at':[3,3]}]", "links[1].id: ""link1"" is already the id of links[0]")>
    <InlineData("[{'id':'link2','type':'rod','a':'ball','at':[2,3]},{'type':'rod','a':'ball2','at':[3,3]}]", "links[1]: has no id, so it is named ""link2"" by its position, but links[0] already has that id")>
    Public Sub Id_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'type':'rod','at':[2,3]}]", "links[0].a: is required")>
    <InlineData("[{'type':'rod','a':1,'at':[2,3]}]", "links[0].a: must be a body's id (a string), not a number")>
    <InlineData("[{'type':'rod','a':null,'at':[2,3]}]", "links[0].a: must be a body's id (a string), not null")>
    <InlineData("[{'type':'rod','a':'bal','at':[2,3]}]", "links[0].a: no body ""bal""")>
    <InlineData("[{'type':'rod','a':'Ball','at':[2,3]}]", "links[0].a: no body ""Ball""")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3]},{'type':'spring','a':'ball','at':[2,3],'stiffness':1},{'type':'rod','a':'ball','b':'bal2'}]", "links[2].b: no body ""bal2""")>
    <InlineData("[{'type':'rod','a':'ball','b':['ball2']}]", "links[0].b: must be a body's id (a string), not an array")>
    <InlineData("[{'type':'rod','a':'ball','b':'ball2','at':[2,3]}]", "links[0]: has both ""b"" and ""at""; give one: the other end is a body (""b"") or a fixed point (""at"")")>
    <InlineData("[{'type':'rod','a':'ball'}]", "links[0]: needs ""b"" (a body) or ""at"" (a fixed point [x, y]) for its other end")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball','stiffness':10}]", "links[0].b: is ""ball"", the same body as a; a link joins two different bodies (use ""at"" for a fixed point)")>
    <InlineData("[{'type':'rod','a':'ball','b':'ramp'}]", "links[0].b: ""ramp"" is a segment, which has no reference point to join (use ""at"" for a point on it)")>
    <InlineData("[{'type':'rod','a':'ramp','b':'ball'}]", "links[0].a: ""ramp"" is a segment, which has no reference point to join (use ""at"" for a point on it)")>
    Public Sub End_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'type':'rod','a':'peg','b':'ball'}]", "links[0].a: ""peg"" is fixed, but end a must be a movable body (swap a and b)")>
    <InlineData("[{'type':'spring','a':'table','b':'box','stiffness':5}]", "links[0].a: ""table"" is fixed, but end a must be a movable body (swap a and b)")>
    <InlineData("[{'type':'rod','a':'peg','b':'table'}]", "links[0]: both ends are fixed (body ""peg"" and body ""table""), so it could never move anything")>
    <InlineData("[{'type':'string','a':'peg','at':[5,4.5]}]", "links[0]: both ends are fixed (body ""peg"" and the point (x = 5, y = 4.5)), so it could never move anything")>
    Public Sub FixedEnd_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'type':'rod','a':'ball','at':'2,3'}]", "links[0].at: must be an [x, y] pair, not a string")>
    <InlineData("[{'type':'rod','a':'ball','at':{'x':2,'y':3}}]", "links[0].at: must be an [x, y] pair, not an object")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3,0]}]", "links[0].at: must be an [x, y] pair, not 3 numbers")>
    <InlineData("[{'type':'rod','a':'ball','at':[2]}]", "links[0].at: must be an [x, y] pair, not 1 numbers")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,'3']}]", "links[0].at[1]: must be a number, not a string")>
    <InlineData("[{'type':'rod','a':'ball','at':[NaN,3]}]", "links[0].at[0]: must be a finite number, not NaN")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,-1e400]}]", "links[0].at[1]: must be a finite number (-1e400 is too large)")>
    Public Sub At_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2'}]", "links[0].stiffness: is required")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':0}]", "links[0].stiffness: must be greater than 0")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':-40}]", "links[0].stiffness: must be greater than 0")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':'40'}]", "links[0].stiffness: must be a number, not a string")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':Infinity}]", "links[0].stiffness: must be a finite number, not Infinity")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':40,'rest_length':-0.5}]", "links[0].rest_length: must be 0 or greater")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':40,'rest_length':1e400}]", "links[0].rest_length: must be a finite number (1e400 is too large)")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':40,'damping':-1}]", "links[0].damping: must be 0 or greater")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':40,'damping':null}]", "links[0].damping: must be a number, not null")>
    <InlineData("[{'type':'spring','a':'ball','b':'ball2','stiffness':40,'length':0.5}]", "links[0].length: a spring has no ""length""; its natural length is ""rest_length""")>
    Public Sub Spring_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Theory>
    <InlineData("[{'type':'rod','a':'ball','b':'ball2','length':0}]", "links[0].length: must be greater than 0")>
    <InlineData("[{'type':'string','a':'ball','b':'ball2','length':-1}]", "links[0].length: must be greater than 0")>
    <InlineData("[{'type':'string','a':'ball','b':'ball2','length':true}]", "links[0].length: must be a number, not true")>
    <InlineData("[{'type':'rod','a':'ball','b':'ball2','length':NaN}]", "links[0].length: must be a finite number, not NaN")>
    <InlineData("[{'type':'rod','a':'ball','b':'ball2','length':1,'length':1}]", "links[0].length: appears more than once")>
    <InlineData("[{'type':'rod','a':'ball','b':'ball2','rest_length':1}]", "links[0].rest_length: a rod has no ""rest_length""; its length is ""length""")>
    <InlineData("[{'type':'string','a':'ball','at':[2,4],'rest_length':2}]", "links[0].rest_length: a string has no ""rest_length""; its length is ""length""")>
    Public Sub RodAndString_FieldErrors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    ''' <summary>"ball" at (2, 2) and the point (2, 3.5) are 1.5 m apart; "ball" and "ball2" 1 m.</summary>
    <Theory>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3.5],'length':1.4}]", "links[0].length: a rod's length must be the distance between its ends in the file, 1.5 m, not 1.4 m (they differ by 0.1 m; leave ""length"" out to use the distance)")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3.5],'length':1.6}]", "links[0].length: a rod's length must be the distance between its ends in the file, 1.5 m, not 1.6 m (they differ by 0.1 m; leave ""length"" out to use the distance)")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,3.5],'length':1.500000002}]", "links[0].length: a rod's length must be the distance between its ends in the file, 1.5 m, not 1.500000002 m (they differ by 2E-09 m; leave ""length"" out to use the distance)")>
    <InlineData("[{'type':'rod','a':'ball','b':'ball2','length':2}]", "links[0].length: a rod's length must be the distance between its ends in the file, 1 m, not 2 m (they differ by 1 m; leave ""length"" out to use the distance)")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,2],'length':1}]", "links[0].length: a rod's length must be the distance between its ends in the file, 0 m, not 1 m (they differ by 1 m; leave ""length"" out to use the distance)")>
    <InlineData("[{'type':'string','a':'ball','at':[2,3.5],'length':1.2}]", "links[0].length: a string of 1.2 m cannot reach between its ends, which are 1.5 m apart in the file (0.3 m too short)")>
    <InlineData("[{'type':'string','a':'ball','at':[2,3.5],'length':1.499999998}]", "links[0].length: a string of 1.499999998 m cannot reach between its ends, which are 1.5 m apart in the file (2E-09 m too short)")>
    <InlineData("[{'type':'rod','a':'ball','at':[2,2]}]", "links[0]: the rod's ends are at the same point in the file (x = 2, y = 2), so it would have length 0")>
    <InlineData("[{'type':'string','a':'box','at':[4.5,0.25]}]", "links[0]: the string's ends are at the same point in the file (x = 4.5, y = 0.25), so it needs a ""length"" greater than 0")>
    Public Sub LengthThatDoesNotFitTheFile_Errors(links As String, expected As String)
        Assert.Equal(expected, Fails(links).Message)
    End Sub

    <Fact>
    Public Sub LinkErrorsCarryPlaceAndProblem()
        Dim ex = Fails("[{'type':'rod','a':'ball','at':[2,3]},{'type':'rod','a':'ball','at':[2,3]},{'type':'rod','a':'ball','b':'bal2'}]")
        Assert.Equal("links[2].b", ex.Place)
        Assert.Equal("no body ""bal2""", ex.Problem)
    End Sub

    <Fact>
    Public Sub BodyErrors_AreReportedBeforeLinkErrors()
        ' The link's end is missing too, but the body's radius comes first: the links are checked against valid bodies.
        Dim json = SceneErrorTests.Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'id':'ball','type':'circle','x':2,'y':2,'radius':0,'mass':1}]," &
                                     "'links':[{'type':'rod','a':'nobody','at':[2,3]}]}")
        Assert.Equal("bodies[0].radius: must be greater than 0", Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(json)).Message)
    End Sub
End Class
