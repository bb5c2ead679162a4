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

    ''' <summary>
    ''' Two 50 g balls on a soft spring (k = 10 N/m, natural length 0.3 m), flying apart at 1 m/s in free space, also
    ''' joined by a string 4.5 cm longer than the spring: the spring stretches by up to 5 cm, so the string snaps
    ''' taut about 56 ms on. Each look further doubles the stretch looked at, so the look that finds the snap asked
    ''' for tens of milliseconds past it. Nothing may be integrated past an event found: there the group no longer
    ''' holds, and its forces can run away (a contact pulling harder and harder on a light ball it should have let
    ''' go took the step down to 10⁻¹⁵ s and failed). The steps end within one step of the snap.
    ''' </summary>
    <Fact>
    Public Sub LookingFurther_StopsAtTheFirstEventFound()
        Dim a As New Circle(New Vector(1, 1), 0.05, 0.05, Vector.Zero, "a")
        Dim b As New Circle(New Vector(1.3, 1), 0.05, 0.05, New Vector(1, 0), "b")
        Dim links As New List(Of Link) From {
            Link.CreateSpring(a, b, 10, 0.3),
            Link.CreateTie(LinkKind.String, a, b, 0.345)
        }
        Dim m As New ConstrainedMotion(New Shape() {a, b}, links, Array.Empty(Of Constraint)(), 0, 0, Nothing, 0.3)
        Dim looked = m.TransitionTime
        Dim looks = 0
        Do While m.LookFurther(looked)
            looks += 1
            Assert.True(looks < 1000, "the snap was never found")
            looked = m.TransitionTime
        Loop
        ' x(t) = 0.3 + 0.05 sin(20 t) for the spring alone (ω² = k/μ = 10/0.025): it reaches 0.345 at asin(0.9)/20.
        Dim snap = Math.Asin(0.9) / 20
        Assert.InRange(m.TransitionTime, snap - 0.000001, snap + 0.000001)
        Assert.True(looks >= 3, $"the snap was found within {looks} looks further, not mid-way through a long one")
        Assert.True(m.IntegratedTo - m.TransitionTime < 0.005, $"integrated to {m.IntegratedTo} s, past the snap at {m.TransitionTime} s")
    End Sub
End Class
