Option Strict On
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>What a teacher types stays; the tables tell the truth; a container too small is refused.</summary>
Public Class TypedValuesAndTablesTests
    <Fact>
    Public Sub TypedValues_StayThroughPauseResetAndAdd_WhileABodyIsBeingPlaced()
        Dim h As New PresenterHarness()
        h.P.InputChanged(InputField.Mass, "7")
        h.P.InputChanged(InputField.ContainerWidth, "6")
        h.P.BeginAddCircle() ' radius 0.25 and mass 7, as typed
        Assert.Equal(7.0, h.P.Draft.Mass)
        h.P.TogglePause()
        h.P.Reset()
        h.P.BeginAddCircle()
        h.P.BeginAddRectangle()
        h.P.InputChanged(InputField.Mass, "7.50")
        h.P.TogglePause()
        Assert.Equal("7.50", h.P.Inputs.MassText)
        Assert.Equal("6", h.P.Inputs.ContainerWidthText)
        ' Nothing asked the window to overwrite a box.
        Assert.Equal(0, h.View.InputsShown)
    End Sub

    <Fact>
    Public Sub WhilePaused_TheTablesAndTotals_ShowTheStateNow()
        Dim h As New PresenterHarness(New World(8, 5, 9.81, 1.0))
        Dim ball = h.Ball(4, 4, mass:=2)
        For k = 1 To 13
            h.P.Tick(1 / 60.0) ' between two snapshots
        Next
        h.P.TogglePause()
        Dim row = h.P.Snapshot.Row(0, 0)
        Assert.Equal(ball.Velocity.Y, row.Velocity.Y)
        Assert.Equal(ball.Position, row.Position)
        Assert.Equal(Units.Sig(ball.Velocity.Y), h.P.Snapshot.Cells(0, 0)(5))
        ' The totals are of the same moment as the rows.
        Dim p = row.Velocity * row.Mass
        Assert.Contains("Σp" & Units.Nbsp & "=" & Units.Nbsp & Units.SigPair(p).Replace(" "c, Units.Nbsp), h.P.TotalsText, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ACueShotWhilePaused_ShowsInTheTableAtOnce()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        h.Ball(4, 2)
        h.P.TogglePause()
        Dim shownBefore = h.View.BodiesShown
        h.Drag(PointerButton.Left, 4, 2, 3.5, 2)
        Assert.True(h.View.BodiesShown > shownBefore)
        Assert.Equal("2.00", h.P.Snapshot.Cells(0, 0)(4))
    End Sub

    <Fact>
    Public Sub WhileRunning_TheSnapshotFollowsAboutTenTimesASecond_AndItsTimeIsTheTotals()
        Dim h As New PresenterHarness(New World(8, 5, 9.81, 1.0))
        h.Ball(4, 4)
        Dim shown = h.View.BodiesShown
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Assert.InRange(h.View.BodiesShown - shown, 8, 12)
        Assert.Contains("t" & Units.Nbsp & "=" & Units.Nbsp & Units.Sig(h.P.Snapshot.Time, 4), h.P.TotalsText, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AContainerTooSmallForItsBalls_IsRefusedWithTheReason_AndNothingChanges()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(60, 0.3, 0.1))
        Dim w = h.P.World.Width
        Dim before = h.P.World.Circles.Select(Function(c) c.Position).ToArray()
        h.P.ResizeContainer("0.6", "0.6")
        Assert.Equal(w, h.P.World.Width)
        Assert.Equal(before, h.P.World.Circles.Select(Function(c) c.Position).ToArray())
        Assert.Contains("its 60 balls would not fit in it without overlapping", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains("It keeps its size.", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AContainerThatFits_IsSoundAtOnce_EvenWhilePaused()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(60, 0.3, 0.1))
        h.P.TogglePause()
        Dim side = h.P.World.Width * 0.75
        h.P.ResizeContainer(side.ToString(Globalization.CultureInfo.InvariantCulture), side.ToString(Globalization.CultureInfo.InvariantCulture))
        Assert.Equal(side, h.P.World.Width, 9)
        Assert.Null(Placement.FindProblem(h.P.World))
        SceneFile.Load(SceneFile.Save(h.P.World))
    End Sub
End Class

''' <summary>Limits and numbers: nothing tiny, huge, infinite or 300 digits long reaches the screen.</summary>
Public Class LimitsAndNumbersTests
    <Fact>
    Public Sub TinyRadiusAndMass_AreBroughtUpToTheLimits_WithAMessage()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("1e-300", "1e-300", False)
        Assert.Equal(InputLimits.MinRadius, h.P.Draft.Radius)
        Assert.Equal(InputLimits.MinMass, h.P.Draft.Mass)
        Assert.StartsWith("radius set to the minimum, 0.0100 m, mass set to the minimum, 0.0100 kg.", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal("0.01", h.P.Inputs.RadiusText)
        h.LeftClick(4, 2.5)
        h.P.TogglePause()
        Assert.Contains("check texts ok", h.TraceLines)
        ' The hardest cue on the lightest ball: Δv = 40 N·s / 0.01 kg, written short.
        Dim ball = Assert.Single(h.P.World.Circles)
        Dim s = h.Px(ball.Position.X, ball.Position.Y), back = h.Px(ball.Position.X - 3, ball.Position.Y)
        h.P.PointerDown(PointerButton.Left, s.X, s.Y)
        h.P.PointerMove(back.X, back.Y)
        Assert.Equal("J = 12.0 N·s   Δv = J/m = 1200 m/s", h.P.CueLabel.Replace(Units.Nbsp, " "c))
    End Sub

    <Theory>
    <InlineData(0.0, "0")>
    <InlineData(18.6432, "18.6")>
    <InlineData(-0.35, "−0.350")>
    <InlineData(1234.6, "1235")>
    <InlineData(0.0123456, "0.0123")>
    <InlineData(0.09996, "0.100")>
    <InlineData(9.996, "10.0")>
    <InlineData(123456.0, "1.23×10⁵")>
    <InlineData(1.0E-300, "1.00×10⁻³⁰⁰")>
    <InlineData(-2.5E+300, "−2.50×10³⁰⁰")>
    <InlineData(0.00099996, "1.00×10⁻³")>
    Public Sub Sig_WritesThreeSignificantFigures(value As Double, expected As String)
        Assert.Equal(expected, Units.Sig(value))
    End Sub

    <Fact>
    Public Sub Sig_NeverWritesNaN()
        Assert.Equal("not a number", Units.Sig(Double.NaN))
        Assert.Equal("18.6" & Units.Nbsp & "J", Units.Quantity(18.64, "J"))
    End Sub

    <Fact>
    Public Sub AFileWithATinyBall_IsRefusedWithThePlace_AndTheSceneIsKept()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-tiny-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            IO.File.WriteAllText(path, "{""format"":""physics-scene/1"",""world"":{""width"":4,""height"":3},""bodies"":[{""type"":""circle"",""x"":1,""y"":1,""radius"":1e-300,""mass"":1}]}")
            Dim h As New PresenterHarness(store:=New SceneFileStore())
            Dim before = h.P.World
            h.P.OpenScene(path)
            Assert.Same(before, h.P.World)
            Assert.Equal("Could not open " & IO.Path.GetFileName(path) & ": bodies[0].radius: 1.00×10⁻³⁰⁰ m is below the smallest this app shows, 0.0100 m. The scene on screen is kept.", h.View.LastMessage)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub ArrowScale_ShrinksForFastBalls_KeysAtARoundSpeed_AndGrowsBackWhenTheySlow()
        Dim a As New ArrowScale()
        Assert.Equal(0.25, a.Seconds)
        a.Update(100, 1.25) ' a 100 m/s ball, a quarter of a 5 m box for the longest arrow
        Assert.True(100 * a.Seconds <= 1.25, $"arrow {100 * a.Seconds} m")
        Assert.Equal(0.01, a.Seconds, 12)
        Assert.Equal(50.0, a.LegendSpeed(100, 60), 12) ' at 1 px per m/s, the largest round speed within 60 px
        a.Update(90, 1.25)
        Assert.Equal(0.01, a.Seconds, 12) ' no flicker for small changes
        a.Update(1, 1.25)
        Assert.Equal(0.25, a.Seconds, 12)
    End Sub

    <Fact>
    Public Sub FastBalls_DrawArrowsThatStayInTheContainer()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(4, 2.5)
        h.P.World.SetVelocity(ball, New Vector(500, 0))
        h.P.TogglePause()
        Assert.True(500 * h.P.Arrows.Seconds <= 0.25 * 5, $"a 500 m/s arrow is {500 * h.P.Arrows.Seconds} m long")
    End Sub
End Class

''' <summary>Messages, files and the log: every problem says what and where, in full.</summary>
Public Class MessagesAndFilesTests
    <Fact>
    Public Sub SavingWhereItCannotBeWritten_NamesTheFileAndWhy_NotATemporaryFile()
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        ' /proc refuses new files even to root, as a read-only folder does to a teacher.
        h.P.SaveScene("/proc/demo.json")
        Dim message = h.View.LastMessage
        Assert.StartsWith("Could not save demo.json: ", message, StringComparison.Ordinal)
        Assert.Contains("/proc", message, StringComparison.Ordinal)
        Assert.Contains("nothing was written", message, StringComparison.Ordinal)
        Assert.DoesNotContain(".tmp", message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AFileNestedTooDeeply_SaysSo()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-deep-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            IO.File.WriteAllText(path, "{""format"":""physics-scene/1"",""x"":" & New String("["c, 5000) & New String("]"c, 5000) & "}")
            Dim h As New PresenterHarness(store:=New SceneFileStore())
            h.P.OpenScene(path)
            Assert.Equal("Could not open " & IO.Path.GetFileName(path) & ": document: is nested too deeply: more than 32 levels of brackets (a scene needs 5 at most)", h.View.LastMessage)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub ABodyWithoutAColour_GetsTheSameOneEveryTimeItsFileIsOpened()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-colour-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            IO.File.WriteAllText(path, "{""format"":""physics-scene/1"",""world"":{""width"":4,""height"":3},""bodies"":[{""id"":""a"",""type"":""circle"",""x"":1,""y"":1,""radius"":0.2,""mass"":1},{""id"":""b"",""type"":""circle"",""x"":2,""y"":1,""radius"":0.2,""mass"":1}]}")
            Dim first As New PresenterHarness(store:=New SceneFileStore())
            first.P.OpenScene(path)
            Dim second As New PresenterHarness(store:=New SceneFileStore())
            second.P.OpenScene(path)
            Assert.Equal(first.P.World.Find("a").Color, second.P.World.Find("a").Color)
            Assert.Equal(BodyColours.ForId("a"), first.P.World.Find("a").Color)
            Assert.NotEqual(first.P.World.Find("a").Color, first.P.World.Find("b").Color)
            Assert.True(BodyColours.ShowsOnBothCanvases(BodyColours.Parse(BodyColours.ForId("b"), -1)))
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub OpenAndSave_StartInTheScenesFolder_ThenWhereTheTeacherWent()
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.SceneFolder = "/somewhere/scenes"
        Assert.Equal("/somewhere/scenes", h.P.SceneFolder)
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-folder-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            h.P.SaveScene(path)
            Assert.Equal(IO.Path.GetDirectoryName(IO.Path.GetFullPath(path)), h.P.SceneFolder)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub ASceneWithoutWalls_IsDrawnWithoutThem_AndSaysSo()
        Dim path = IO.Path.Combine(ProcessRunner.RepoRoot, "scenes", "head-on.json")
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.OpenScene(path)
        Assert.False(h.P.HasWalls)
        Assert.Contains("no walls", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ABallRestingAtEEqualsOne_IsOneRowOfTheLog_NotHundreds()
        Dim h As New PresenterHarness(New World(4, 3, 9.81, 1.0))
        h.Ball(2, 0.2015, 0.2) ' 1.5 mm above the floor: it bounces about 29 times a second for ever
        For k = 1 To 360
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(h.P.Log.TotalSeen > 150, $"{h.P.Log.TotalSeen} bounces in 6 s")
        Assert.Equal(1, h.P.Log.Count)
        Dim row = h.P.Log(0)
        Assert.Equal(h.P.Log.TotalSeen, row.Repeats)
        Assert.StartsWith("1 bounced " & row.Repeats & " times on the floor", row.Text, StringComparison.Ordinal)
        Assert.Equal("1 ↔ floor  (" & row.Repeats & " times)", row.Cells()(1))
    End Sub

    <Fact>
    Public Sub TheTutorial_NamesOnlyControlsTheWindowHas()
        Dim all = String.Join(vbLf, HelpTexts.Tutorial.Select(Function(t) t.Text))
        Dim quoted = Text.RegularExpressions.Regex.Matches(all, """([^""]+)""").Cast(Of Text.RegularExpressions.Match)().Select(Function(m) m.Groups(1).Value)
        ' Quoted words are either a control's caption or a message the app shows.
        For Each q In quoted
            Assert.True(Captions.All.Contains(q) OrElse q = InputLimits.SpawnFirstMessage, $"the tutorial names ""{q}"", which is not on the window")
        Next
        Assert.DoesNotContain("Cancel", all, StringComparison.Ordinal)
    End Sub
End Class

''' <summary>The form is a passive view: slider scaling and the error policy live in the presenter.</summary>
Public Class PassiveViewTests
    <Fact>
    Public Sub Sliders_AreScaledHere_NotInTheWindow()
        Dim h As New PresenterHarness()
        h.P.GravitySliderMoved(981)
        Assert.Equal(9.81, h.P.World.Gravity, 12)
        h.P.SetGravity(24.79)
        Assert.Equal(2479, h.P.GravityPosition)
        h.P.GravitySliderMoved(99999)
        Assert.Equal(GravityMark.Maximum, h.P.World.Gravity)
        h.P.RestitutionSliderMoved(90)
        Assert.Equal(0.9, h.P.World.Restitution, 12)
        Assert.Equal(90, h.P.RestitutionPosition)
        Assert.Equal("Gravity g = 100 m/s²", h.P.GravityText.Replace(Units.Nbsp, " "c))
        Assert.Equal("Restitution e = 0.90  (1 = elastic)", h.P.RestitutionText)
    End Sub

    <Fact>
    Public Sub WhatTheEngineRefuses_IsAMessageAndAPause_NeverACrash()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(4, 2)
        h.P.World.SetVelocity(ball, New Vector(1.0E+200, 0))
        h.P.Tick(1 / 60.0)
        Assert.True(h.P.IsPaused)
        Assert.StartsWith("The simulation stopped: ", h.View.LastMessage, StringComparison.Ordinal)
        Assert.True(h.View.SettingsShown > 0, "the window was told to show the pause")
    End Sub
End Class
