Option Strict On
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' The scene format's forces (scene-format.md, "Forces"): world friction, static friction and air density,
''' each body's own friction and drag, and liquid regions as entries of "bodies" of type "liquid". Read,
''' defaulted, written so that a saved file reopens identically, and every bad value refused with one line
''' that names its place. JSON is written with ' for ".
''' </summary>
Public Class SceneForcesTests
    Private Shared Function Scene(world As String, bodies As String) As String
        Return SceneErrorTests.Q("{'format':'physics-scene/1','world':{'width':8,'height':5" & world & "},'bodies':[" & bodies & "]}")
    End Function

    Private Const BoxJson As String = "{'id':'box','type':'rectangle','x':1,'y':0,'width':0.5,'height':0.5,'fixed':false,'mass':2"

    Private Shared Function Fails(json As String) As SceneFormatException
        Return Assert.Throws(Of SceneFormatException)(Function() SceneFile.Load(json))
    End Function

    <Fact>
    Public Sub AFileWithoutForces_MeansNoFrictionNoAirNoLiquid()
        Dim w = SceneFile.Load(Scene("", BoxJson & "},{'id':'ball','type':'circle','x':4,'y':2,'radius':0.2,'mass':1}"))
        Assert.Equal(0.0, w.Friction)
        Assert.Null(w.StaticFriction)
        Assert.Equal(0.0, w.AirDensity)
        Assert.Empty(w.Liquids)
        Assert.False(w.HasDragOrLiquids)
        For Each b In w.Bodies
            Assert.Null(b.Friction)
            Assert.Null(b.StaticFriction)
            Assert.Equal(0.0, b.DragCoefficient)
            Assert.Equal(0.0, b.LinearDrag)
        Next
        Assert.Equal(0.0, w.KineticFrictionOf(w.Find("box")))
        Assert.Equal(0.0, w.StaticFrictionOf(w.Find("box")))
        ' Written as before: none of the new fields appear.
        Dim text = SceneFile.Save(w)
        For Each name In {"friction", "air_density", "drag_coefficient", "linear_drag", "liquid"}
            Assert.DoesNotContain(name, text)
        Next
    End Sub

    <Fact>
    Public Sub WorldAndBodyFields_AreRead()
        Dim w = SceneFile.Load(Scene(",'friction':0.3,'static_friction':0.5,'air_density':1.2",
            BoxJson & ",'friction':0.6,'static_friction':0.8,'drag_coefficient':1.05,'linear_drag':0.25}," &
            "{'id':'ramp','type':'segment','x1':3,'y1':0,'x2':6,'y2':2,'friction':0.2}," &
            "{'id':'ball','type':'circle','x':4,'y':4,'radius':0.2,'mass':1,'friction':0.9,'drag_coefficient':0.47}"))
        Assert.Equal(0.3, w.Friction)
        Assert.Equal(0.5, w.StaticFriction)
        Assert.Equal(1.2, w.AirDensity)
        Dim box = w.Find("box"), ramp = w.Find("ramp"), ball = w.Find("ball")
        Assert.Equal(0.6, box.Friction)
        Assert.Equal(0.8, box.StaticFriction)
        Assert.Equal(1.05, box.DragCoefficient)
        Assert.Equal(0.25, box.LinearDrag)
        ' A segment's own μk; its μs follows its own μk, not the world's μs.
        Assert.Equal(0.2, w.KineticFrictionOf(ramp))
        Assert.Equal(0.2, w.StaticFrictionOf(ramp))
        ' A circle keeps what it was given (the app shows it), though it takes no friction.
        Assert.Equal(0.9, ball.Friction)
        Assert.Equal(0.47, ball.DragCoefficient)
        ' Walls use the world's values.
        Assert.Equal(0.3, w.KineticFrictionOf(Nothing))
        Assert.Equal(0.5, w.StaticFrictionOf(Nothing))
        Assert.True(w.HasDragOrLiquids)
    End Sub

    <Fact>
    Public Sub AFixedBodysDrag_IsCheckedThenIgnored()
        Dim w = SceneFile.Load(Scene("", "{'id':'peg','type':'circle','x':4,'y':2,'radius':0.2,'fixed':true,'drag_coefficient':1,'linear_drag':2}"))
        Assert.Equal(0.0, w.Find("peg").DragCoefficient)
        Assert.Equal(0.0, w.Find("peg").LinearDrag)
        Assert.Equal("bodies[0].linear_drag: must be 0 or greater",
                     Fails(Scene("", "{'id':'peg','type':'circle','x':4,'y':2,'radius':0.2,'fixed':true,'linear_drag':-2}")).Message)
    End Sub

    <Fact>
    Public Sub Liquids_AreEntriesOfBodies_WithIdsSharedWithTheBodies()
        Dim w = SceneFile.Load(Scene("",
            "{'type':'liquid','x':0,'y':0,'width':4,'height':1.5,'density':1000,'drag_coefficient':0.8,'linear_drag':3,'color':'#1e88e5'}," &
            BoxJson & "}," &
            "{'id':'oil','type':'liquid','x':4,'y':0,'width':4,'height':1,'density':800}"))
        Assert.Equal(2, w.Liquids.Count)
        Assert.Single(w.Bodies)
        Dim water = w.Liquids(0)
        Assert.Equal("1", water.Id) ' its 1-based place in "bodies", as for a body
        Assert.Equal(New Vector(0, 0), water.Min)
        Assert.Equal(4.0, water.Width)
        Assert.Equal(1.5, water.Surface)
        Assert.Equal(1000.0, water.Density)
        Assert.Equal(0.8, water.DragCoefficient)
        Assert.Equal(3.0, water.LinearDrag)
        Assert.Equal("#1e88e5", water.Color)
        Assert.Equal("oil", w.Liquids(1).Id)
        Assert.Equal(0.0, w.Liquids(1).LinearDrag)
        Assert.Same(w.Liquids(1), w.FindLiquid("oil"))
        Assert.True(w.HasDragOrLiquids)
    End Sub

    <Fact>
    Public Sub ASceneWithEveryForce_ReopensIdentically()
        Dim text = Scene(",'friction':0.1,'static_friction':0.35,'air_density':1.2041",
            "{'id':'water','type':'liquid','x':0,'y':0,'width':3.3,'height':1.1,'density':997.05,'drag_coefficient':0.1,'linear_drag':0.3,'color':'#1e88e5'}," &
            BoxJson & ",'friction':0.61,'drag_coefficient':1.05,'linear_drag':0.1},{'id':'ball','type':'circle','x':4,'y':4,'radius':0.2,'mass':1,'static_friction':0.7}," &
            "{'id':'ramp','type':'segment','x1':3,'y1':0,'x2':6,'y2':2,'friction':0.2,'static_friction':0.25}")
        Dim first = SceneFile.Load(text)
        Dim saved = SceneFile.Save(first)
        Dim again = SceneFile.Load(saved)
        Assert.Equal(saved, SceneFile.Save(again))
        Assert.Equal(first.Friction, again.Friction)
        Assert.Equal(first.StaticFriction, again.StaticFriction)
        Assert.Equal(first.AirDensity, again.AirDensity)
        For k = 0 To first.Bodies.Count - 1
            Dim a = first.Bodies(k), b = again.Bodies(k)
            Assert.Equal(a.Id, b.Id)
            Assert.Equal(a.Friction, b.Friction)
            Assert.Equal(a.StaticFriction, b.StaticFriction)
            Assert.Equal(a.DragCoefficient, b.DragCoefficient)
            Assert.Equal(a.LinearDrag, b.LinearDrag)
        Next
        Assert.Single(again.Liquids)
        Dim w1 = first.Liquids(0), w2 = again.Liquids(0)
        Assert.Equal(w1.Id, w2.Id)
        Assert.Equal(w1.Min, w2.Min)
        Assert.Equal(w1.Width, w2.Width)
        Assert.Equal(w1.Height, w2.Height)
        Assert.Equal(w1.Density, w2.Density)
        Assert.Equal(w1.DragCoefficient, w2.DragCoefficient)
        Assert.Equal(w1.LinearDrag, w2.LinearDrag)
        Assert.Equal(w1.Color, w2.Color)
        Assert.Contains("""type"": ""liquid""", saved)
        Assert.Contains("""air_density"": 1.2041", saved)
    End Sub

    <Theory>
    <InlineData(",'friction':-0.1", "", "world.friction: must be 0 or greater")>
    <InlineData(",'friction':'rough'", "", "world.friction: must be a number, not a string")>
    <InlineData(",'static_friction':-1", "", "world.static_friction: must be 0 or greater")>
    <InlineData(",'friction':0.5,'static_friction':0.4", "", "world.static_friction: must be at least friction (0.5), not 0.4")>
    <InlineData(",'air_density':-1.2", "", "world.air_density: must be 0 or greater")>
    <InlineData(",'air_density':Infinity", "", "world.air_density: must be a finite number, not Infinity")>
    <InlineData("", "{'type':'circle','x':4,'y':2,'radius':0.2,'mass':1,'friction':-0.2}", "bodies[0].friction: must be 0 or greater")>
    <InlineData("", "{'type':'circle','x':4,'y':2,'radius':0.2,'mass':1,'friction':0.5,'static_friction':0.2}", "bodies[0].static_friction: must be at least its friction (0.5), not 0.2")>
    <InlineData(",'friction':0.4", "{'type':'segment','x1':0,'y1':0,'x2':1,'y2':1,'static_friction':0.3}", "bodies[0].static_friction: must be at least world.friction (0.4), not 0.3")>
    <InlineData("", "{'type':'circle','x':4,'y':2,'radius':0.2,'mass':1,'drag_coefficient':-0.47}", "bodies[0].drag_coefficient: must be 0 or greater")>
    <InlineData("", "{'type':'circle','x':4,'y':2,'radius':0.2,'mass':1,'linear_drag':1e999}", "bodies[0].linear_drag: must be a finite number (1e999 is too large)")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':8,'height':1,'density':0}", "bodies[0].density: must be greater than 0")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':8,'height':1,'density':-1000}", "bodies[0].density: must be greater than 0")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':8,'height':1}", "bodies[0].density: is required")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':0,'height':1,'density':1000}", "bodies[0].width: must be greater than 0")>
    <InlineData("", "{'type':'liquid','y':0,'width':1,'height':1,'density':1000}", "bodies[0].x: is required")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':8,'height':1,'density':1000,'drag_coefficient':-1}", "bodies[0].drag_coefficient: must be 0 or greater")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':8,'height':1,'density':1000,'linear_drag':-1}", "bodies[0].linear_drag: must be 0 or greater")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':8,'height':1,'density':1000,'color':'blue'}", "bodies[0].color: must be a colour ""#rrggbb"" such as ""#e53935"", not ""blue""")>
    <InlineData("", "{'type':'liquid','x':0,'y':0,'width':4,'height':1,'density':1000},{'type':'liquid','x':3,'y':0.5,'width':4,'height':1,'density':800}", "bodies[1]: overlaps the liquid bodies[0] (liquids may not overlap each other)")>
    <InlineData("", "{'id':'w','type':'liquid','x':0,'y':0,'width':4,'height':1,'density':1000},{'id':'w','type':'circle','x':6,'y':3,'radius':0.2,'mass':1}", "bodies[1].id: ""w"" is already the id of bodies[0]")>
    Public Sub BadValues_AreRefusedWithOneLocatedLine(world As String, bodies As String, expected As String)
        Dim message = Fails(Scene(world, bodies)).Message
        Assert.Equal(expected, message)
        Assert.DoesNotContain(vbLf, message)
    End Sub

    <Fact>
    Public Sub TouchingLiquids_AreAllowed()
        Dim w = SceneFile.Load(Scene("", "{'type':'liquid','x':0,'y':0,'width':4,'height':1,'density':1000},{'type':'liquid','x':4,'y':0,'width':4,'height':1,'density':800},{'type':'liquid','x':0,'y':1,'width':4,'height':1,'density':700}"))
        Assert.Equal(3, w.Liquids.Count)
    End Sub

    <Fact>
    Public Sub TheWorld_RefusesOverlappingLiquidsAndBadCoefficients_AndLeavesItselfAsItWas()
        Dim w As New World(8, 5)
        w.Add(New Liquid(New Vector(0, 0), 4, 1, 1000, "water"))
        Assert.Throws(Of ArgumentException)(Sub() w.Add(New Liquid(New Vector(2, 0.5), 4, 1, 800)))
        Assert.Throws(Of ArgumentException)(Sub() w.Add(New Circle(New Vector(6, 3), 0.2, 1, id:="water")))
        Assert.Single(w.Liquids)
        Assert.Throws(Of ArgumentOutOfRangeException)(Sub() w.Friction = -0.1)
        Assert.Throws(Of ArgumentOutOfRangeException)(Sub() w.AirDensity = Double.NaN)
        w.Friction = 0.5
        Assert.Throws(Of ArgumentOutOfRangeException)(Sub() w.StaticFriction = 0.4)
        Dim box = Rectangle.CreateMovable(New Vector(5, 0), 1, 1, 1)
        w.Add(box)
        Assert.Throws(Of ArgumentOutOfRangeException)(Sub() w.SetFriction(box, Nothing, 0.4))
        Assert.Throws(Of ArgumentOutOfRangeException)(Sub() w.SetDrag(box, -1, 0))
        Assert.Throws(Of ArgumentOutOfRangeException)(Function() New Liquid(New Vector(0, 0), 1, 1, 0))
        Assert.Equal(0.5, w.Friction)
        Assert.Null(w.StaticFriction)
        Assert.Null(box.Friction)
        Assert.Equal(0.0, box.DragCoefficient)
        w.SetFriction(box, 0.7, Nothing)
        Assert.Equal(0.7, w.StaticFrictionOf(box))
    End Sub
End Class
