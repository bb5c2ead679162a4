Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The Maths used window has a page for every model the app uses.</summary>
Public Class HelpPagesTests
    <Theory>
    <InlineData("Springs", "Hooke")>
    <InlineData("Rods and strings", "T = m (v²/L + g cos θ)")>
    <InlineData("pendulum", "K(k)")>
    <InlineData("shapes in contact", "Minkowski")>
    <InlineData("Euler and Verlet", "x → 2x − x_previous + a h²")>
    <InlineData("integrating", "Dormand–Prince")>
    <InlineData("Collision: the impulse", "j = −(1 + e) u")>
    <InlineData("Maxwell–Boltzmann", "f(v)")>
    <InlineData("Friction", "s = v² / (2 μk g)")>
    <InlineData("Friction", "tan θ ≤ μs")>
    <InlineData("Friction", "double-click its μk or μs cell in the Rectangles or Bodies table")>
    Public Sub TheMathsWindow_HasAPageForEveryModel(titlePart As String, formula As String)
        Dim page = HelpTexts.Maths.SingleOrDefault(Function(t) t.Title.Contains(titlePart, StringComparison.Ordinal))
        Assert.True(page IsNot Nothing, "no Maths used page on " & titlePart)
        Assert.Contains(formula, page.Text, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub EveryPageTitle_IsShortEnoughForTheList()
        For Each t In HelpTexts.Maths.Concat(HelpTexts.Tutorial)
            Assert.True(t.Title.Length <= 60, t.Title)
        Next
    End Sub
End Class
