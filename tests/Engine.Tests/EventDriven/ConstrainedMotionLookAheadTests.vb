Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' How far a chain's integrated motion is integrated before anything asks further: its first look is one step,
''' whatever length the error control then gives it, not the stretch of the first step's guess.
''' </summary>
Public Class ConstrainedMotionLookAheadTests
    ''' <summary>
    ''' Two 50 g balls on a stiff spring (k = 4573 N/m, a period of about 15 ms), also joined by a slack 4 m string, so
    ''' that the group can end by itself and is looked at step by step. The first step's guess is a hundredth of the
    ''' string's pendulum period (about 38 ms); the error control cuts it to a fraction of a millisecond. Integrating
    ''' up to the guess took hundreds of steps after every collision that made such a group anew (5 s of CPU instead
    ''' of 1 in a scene of three balls): the first look must end within a few milliseconds.
    ''' </summary>
    <Fact>
    Public Sub StiffSpringGroup_FirstLook_IsOneStep()
        Dim a As New Circle(New Vector(1, 1), 0.05, 0.05, Vector.Zero, "a")
        Dim b As New Circle(New Vector(1.3, 1), 0.05, 0.05, New Vector(1, 0), "b")
        Dim links As New List(Of Link) From {
            Link.CreateSpring(a, b, 4573, 0.3),
            Link.CreateTie(LinkKind.String, a, b, 4)
        }
        Dim m As New ConstrainedMotion(New Shape() {a, b}, links, Array.Empty(Of Constraint)(), 0, 9.81, Nothing, 0.3)
        Dim looked = m.TransitionTime
        Assert.True(looked > 0, $"looked to {looked} s")
        Assert.True(looked < 0.002, $"looked to {looked} s on its first look (the first step's guess is {0.06 * Math.Sqrt(4 / 9.81)} s)")
        ' It goes on from there when asked: the ends fly apart no further than the string allows, nothing ends it.
        Assert.True(m.LookFurther(looked))
        Assert.True(m.TransitionTime > looked)
    End Sub
End Class
