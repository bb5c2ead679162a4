Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The Scenes menu by topic: every lesson of the scenes folder under a topic, in order, each line short.</summary>
Public Class LessonTopicsTests
    Private Shared ReadOnly Folder As String = IO.Path.Combine(ProcessRunner.RepoRoot, "scenes")

    <Fact>
    Public Sub EveryLessonOfTheScenesFolder_IsUnderATopic_AndOnlyTheDemoIsLeftForMore()
        Dim lessons = LessonIndex.Read(Folder)
        Assert.True(lessons.Count >= 20)
        Dim menu = LessonTopics.Group(lessons)
        ' Every lesson once, in topics in menu order.
        Assert.Equal(lessons.Count, menu.Sum(Function(t) t.Lessons.Count))
        Assert.Equal(lessons.Select(Function(l) l.FileName).OrderBy(Function(n) n, StringComparer.Ordinal),
                     menu.SelectMany(Function(t) t.Lessons).Select(Function(l) l.FileName).OrderBy(Function(n) n, StringComparer.Ordinal))
        Dim order = menu.Select(Function(t) LessonTopics.Names.ToList().IndexOf(t.Topic)).ToList()
        Assert.Equal(order.OrderBy(Function(i) i), order)
        Dim more = menu.Where(Function(t) t.Topic = LessonTopics.More).SelectMany(Function(t) t.Lessons).Select(Function(l) l.FileName).ToList()
        Assert.Equal("demo.json", more.Single())
        Assert.Equal("Collisions", menu(0).Topic)
        Assert.Equal("head-on.json", menu(0).Lessons(0).FileName)
    End Sub

    <Fact>
    Public Sub EveryLineOfTheMenu_IsShort_SoItStaysOnAScreen()
        For Each t In LessonTopics.Group(LessonIndex.Read(Folder))
            Assert.True(t.Topic.Length <= 30, t.Topic)
            For Each l In t.Lessons
                Assert.True(l.Title.Length <= 48, $"'{l.Title}' is {l.Title.Length} characters long")
            Next
        Next
    End Sub

    <Fact>
    Public Sub ASceneTheTeacherSaved_IsUnderMoreScenes_AfterTheLessons()
        Dim lessons = {New Lesson("/x/head-on.json", "Head-on", ""), New Lesson("/x/my-demo.json", "My demo", ""), New Lesson("/x/ideal-gas.json", "Gas", "")}
        Dim menu = LessonTopics.Group(lessons)
        Assert.Equal("Collisions|Gases|" & LessonTopics.More, String.Join("|", menu.Select(Function(t) t.Topic)))
        Assert.Equal("my-demo.json", menu(2).Lessons.Single().FileName)
    End Sub
End Class
