Option Strict On

''' <summary>
''' The Scenes menu's topics, in menu order, and which lesson belongs to which: the menu shows the
''' topics, and each opens a short list of its lessons, so no line runs off a screen. A scene file
''' not named here (one the teacher saved in the scenes folder) is under <see cref="More"/>.
''' </summary>
Public Module LessonTopics
    ''' <summary>The topic of scene files not named here.</summary>
    Public Const More As String = "More scenes"

    ''' <summary>The topics in menu order, each with the scene files it holds.</summary>
    Private ReadOnly Topics As (Name As String, Files As String())() = {
        ("Collisions", {"head-on.json", "head-on-inelastic.json", "glancing-blow.json", "pool-break.json", "polygons.json"}),
        ("Momentum", {"newtons-cradle.json", "boxes-sliding.json", "pi-31.json", "pi-314.json", "pi-3141.json"}),
        ("Energy", {"bouncing-ball.json", "settling-pile.json", "galton-board.json", "peg-board.json"}),
        ("Gases", {"ideal-gas.json"}),
        ("Pendulums and springs", {"pendulum.json", "cradle-strings.json", "spring-mass.json", "double-pendulum.json", "rope.json"}),
        ("Ramps and boxes", {"ramp.json", "ball-in-v.json", "box-stack.json"}),
        ("Friction", {"inclined-plane.json", "rough-floor.json"}),
        ("Forces", {"terminal-velocity.json", "projectile-air.json", "floating-sinking.json", "bobbing-box.json"})}

    ''' <summary>Every topic's name in menu order, <see cref="More"/> last.</summary>
    Public ReadOnly Property Names As IReadOnlyList(Of String) = Topics.Select(Function(t) t.Name).Concat({More}).ToArray()

    ''' <summary>The topic a scene file belongs to (<see cref="More"/> when it is not one of the lessons named here).</summary>
    Public Function TopicOf(fileName As String) As String
        For Each t In Topics
            If t.Files.Contains(fileName, StringComparer.OrdinalIgnoreCase) Then Return t.Name
        Next
        Return More
    End Function

    ''' <summary>The lessons grouped by topic, in menu order (topics with no lesson left out); within a topic, in the order given.</summary>
    Public Function Group(lessons As IEnumerable(Of Lesson)) As IReadOnlyList(Of (Topic As String, Lessons As IReadOnlyList(Of Lesson)))
        If lessons Is Nothing Then Throw New ArgumentNullException(NameOf(lessons))
        Dim all = lessons.ToList()
        Dim result As New List(Of (Topic As String, Lessons As IReadOnlyList(Of Lesson)))
        For Each name In Names
            Dim topic = name
            Dim members As IReadOnlyList(Of Lesson) = all.Where(Function(l) TopicOf(l.FileName) = topic).ToList()
            If members.Count > 0 Then result.Add((topic, members))
        Next
        Return result
    End Function
End Module
