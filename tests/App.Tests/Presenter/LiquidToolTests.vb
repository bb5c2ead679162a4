Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>The liquid tool: a region dragged out with the density chosen or typed, bad values refused with the reason, Undo, Delete mode, saving.</summary>
Public Class LiquidToolTests
    ''' <summary>A paused world 8 m × 5 m with a box resting on the floor.</summary>
    Private Shared Function Scene() As PresenterHarness
        Dim w As New World(8, 5, 9.81, 0.5)
        w.Add(Rectangle.CreateMovable(New Vector(6, 0), 0.5, 0.5, 50.0, Vector.Zero, "crate"))
        Dim h As New PresenterHarness(w)
        h.P.TogglePause()
        Return h
    End Function

    Private Shared Function State(h As PresenterHarness) As String
        Return SceneFile.Save(h.P.World) & " t=" & h.P.World.Time.ToString("R", CultureInfo.InvariantCulture)
    End Function

    <Fact>
    Public Sub Water_DraggedOut_FillsTheRectangle_AtTheDensityOfWater_DrawnBlue()
        Dim h = Scene()
        h.P.BeginAddWater()
        Assert.Equal(ClickMode.Liquid, h.P.Mode)
        Assert.Equal("1000", h.P.Inputs(InputField.LiquidDensity))
        h.Drag(PointerButton.Left, 5, 2, 1, 0)
        Dim water = h.P.World.Liquids.Single()
        Assert.Equal(1000.0, water.Density)
        ' Any two opposite corners make the same region (to the pixel the pointer lands on).
        Dim pixel = 1 / h.P.View.Scale
        Assert.InRange(water.Min.X, 1 - pixel, 1 + pixel)
        Assert.InRange(water.Min.Y, -pixel, pixel)
        Assert.InRange(water.Surface, 2 - pixel, 2 + pixel)
        Assert.InRange(water.Width, 4 - 2 * pixel, 4 + 2 * pixel)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("placed liquid " & water.Id & " density 1000 from ", StringComparison.Ordinal))
        Assert.Equal(LiquidLook.Water, LiquidLook.ColourOf(water))
        Assert.Equal("ρ = 1000" & Units.Nbsp & "kg/m²", LiquidLook.Label(water))
    End Sub

    <Fact>
    Public Sub Oil_IsLighterThanWater_AndDrawnAmber_ATypedDensityIsUsedAsTyped()
        Dim h = Scene()
        h.P.BeginAddOil()
        h.Drag(PointerButton.Left, 0.5, 3, 2.5, 4)
        Dim oil = h.P.World.Liquids.Single()
        Assert.Equal(900.0, oil.Density)
        Assert.Equal(LiquidLook.Oil, LiquidLook.ColourOf(oil))
        Assert.Equal("ρ = 900" & Units.Nbsp & "kg/m²", LiquidLook.Label(oil))
        h.P.BeginAddLiquid("1260")
        h.Drag(PointerButton.Left, 3, 3, 4.5, 4)
        Dim glycerol = h.P.World.Liquids(1)
        Assert.Equal(1260.0, glycerol.Density)
        Assert.Equal(LiquidLook.Water, LiquidLook.ColourOf(glycerol))
        glycerol.Color = "#43a047"
        Assert.Equal(&H43A047, LiquidLook.ColourOf(glycerol))
    End Sub

    <Theory>
    <InlineData("0", "liquid density (kg/m²) must be greater than 0, not 0")>
    <InlineData("-5", "liquid density (kg/m²) must be greater than 0, not -5")>
    <InlineData("water", "liquid density (kg/m²)")>
    <InlineData("", "liquid density (kg/m²) is empty")>
    Public Sub ABadDensity_IsRefused_NamingTheBox_AndNoToolStarts(typed As String, reason As String)
        Dim h = Scene()
        Dim before = State(h)
        h.P.BeginAddLiquid(typed)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.StartsWith(SimulationPresenter.LiquidMessage & " ", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains(reason, h.View.LastMessage, StringComparison.Ordinal)
        ' What was typed stays in the box, to be corrected.
        Assert.Equal(typed, h.P.Inputs(InputField.LiquidDensity))
        h.Drag(PointerButton.Left, 1, 1, 3, 2)
        Assert.Empty(h.P.World.Liquids)
        Assert.Equal(before, State(h))
    End Sub

    <Fact>
    Public Sub ALiquidOverlappingAnother_IsRefused_SayingWhichAndWhere_AndTheToolStaysOn()
        Dim h = Scene()
        h.P.BeginAddWater()
        h.Drag(PointerButton.Left, 0, 0, 4, 2)
        Dim first = h.P.World.Liquids.Single()
        Dim before = State(h)
        h.P.BeginAddOil()
        h.Drag(PointerButton.Left, 3, 1, 6, 3)
        Assert.Single(h.P.World.Liquids)
        Assert.Equal(before, State(h))
        Assert.StartsWith("Liquids may not overlap: the one drawn from (3", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains("overlaps the liquid " & first.Id & " (", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(ClickMode.Liquid, h.P.Mode)
        ' Beside it, it is taken.
        h.Drag(PointerButton.Left, 4.2, 0, 5.5, 2)
        Assert.Equal(2, h.P.World.Liquids.Count)
    End Sub

    <Fact>
    Public Sub ATooSmallDrag_MakesNoLiquid()
        Dim h = Scene()
        h.P.BeginAddWater()
        h.Drag(PointerButton.Left, 1, 1, 3, 1)
        Assert.Empty(h.P.World.Liquids)
        Assert.StartsWith("That liquid would be too small to see", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AddingAndDeletingALiquid_AreUndoneAndRedone_ToTheLastBit()
        Dim h = Scene()
        Dim s0 = State(h)
        h.P.BeginAddWater()
        h.Drag(PointerButton.Left, 0, 0, 5, 2)
        Dim s1 = State(h)
        Assert.Contains("""liquid""", s1, StringComparison.Ordinal)
        h.P.Undo()
        Assert.Equal(s0, State(h))
        Assert.Empty(h.P.World.Liquids)
        h.P.Redo()
        Assert.Equal(s1, State(h))
        ' Delete mode: a click in the liquid where no body is removes it; Undo brings it back.
        h.P.ToggleDeleteMode()
        h.LeftClick(2, 1)
        h.P.ToggleDeleteMode()
        Assert.Empty(h.P.World.Liquids)
        Assert.Single(h.P.World.Bodies)
        h.P.Undo()
        Assert.Equal(s1, State(h))
        h.P.Redo()
        Assert.Empty(h.P.World.Liquids)
    End Sub

    <Fact>
    Public Sub ADrawnLiquid_IsSavedAndOpensAgain()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-liquid-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            Dim h As New PresenterHarness(store:=New SceneFileStore())
            h.P.TogglePause()
            h.P.BeginAddOil()
            h.Drag(PointerButton.Left, 1, 0, 6, 1.5)
            Dim drawn = h.P.World.Liquids.Single()
            h.P.SaveScene(path)
            Dim again As New PresenterHarness(store:=New SceneFileStore())
            again.P.OpenScene(path)
            Dim opened = again.P.World.Liquids.Single()
            Assert.Equal(drawn.Min, opened.Min)
            Assert.Equal(drawn.Width, opened.Width)
            Assert.Equal(drawn.Height, opened.Height)
            Assert.Equal(900.0, opened.Density)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub TheTutorial_SaysHowToDrawALiquid_AndTheMathsPageGivesTheTextbookResults()
        Dim adding = HelpTexts.Tutorial.Single(Function(t) t.Title = "1. Adding particles")
        Assert.Contains(SimulationPresenter.LiquidCaption, adding.Text, StringComparison.Ordinal)
        Assert.Contains("m/(ρ w)", adding.Text, StringComparison.Ordinal)
        Dim maths = HelpTexts.Maths.Single(Function(t) t.Title.Contains("drag and buoyancy", StringComparison.Ordinal))
        For Each formula In {"v_t = m g / b", "v_t = √(2 m g / (ρ C_d L))", "d = m / (ρ_l w)", "T = 2π √(m / (ρ_l g w))"}
            Assert.Contains(formula, maths.Text, StringComparison.Ordinal)
        Next
    End Sub
End Class
