Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' The crowded lessons' labels: Newton's cradle with its impulses, the pool break with every
''' momentum view on. At many moments every label is placed where it covers no other label, no
''' body, no centre-of-mass marker and not the momentum panel, on the canvas; and the panel never
''' covers the container.
''' </summary>
Public Class CanvasLabelsTests
    ''' <summary>About the size of bold 10-point text: 8 px a character, 16 px high.</summary>
    Private Shared Function Measure(text As String) As (Width As Double, Height As Double)
        Return (8.0 * text.Length + 2, 16.0)
    End Function

    Private Shared Function Lesson(file As String) As PresenterHarness
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.OpenScene(IO.Path.Combine(ProcessRunner.RepoRoot, "scenes", file))
        Assert.StartsWith("Opened " & file, h.P.Message, StringComparison.Ordinal)
        Return h
    End Function

    ''' <summary>Checks every placed label against the others, the bodies, the marker, the panel and the canvas; returns how many were placed.</summary>
    Private Shared Function CheckLabels(h As PresenterHarness, moment As String) As Integer
        Const W As Integer = 800, H2 As Integer = 500
        Dim labels = h.P.LayOutLabels(AddressOf Measure, W, H2)
        Dim canvas As New LabelBox(0, 0, W, H2 - h.P.ScaleStripPixels)
        Dim panel = h.P.MomentumPanelPixels
        For i = 0 To labels.Count - 1
            Dim a = labels(i)
            Assert.True(a.Box.IsInside(canvas), $"{moment}: '{a.Text}' is off the canvas")
            For j = i + 1 To labels.Count - 1
                Assert.False(a.Box.Overlaps(labels(j).Box), $"{moment}: '{a.Text}' and '{labels(j).Text}' overlap")
            Next
            If panel > 0 Then Assert.False(a.Box.Overlaps(New LabelBox(W - panel, 0, panel, H2)), $"{moment}: '{a.Text}' is over the momentum panel")
            For Each b In h.P.World.Bodies
                If b.Kind = ShapeKind.Segment OrElse (a.Inside AndAlso b Is a.Body) Then Continue For
                Assert.False(a.Box.Overlaps(CanvasLabelLayout.ScreenBox(b, h.P.View, 1.0)), $"{moment}: '{a.Text}' covers {b.Id}")
            Next
            If h.P.ShowCentreOfMass AndAlso h.P.Momentum.HasBodies Then
                Dim c = h.P.View.ToScreen(h.P.Momentum.CentreOfMass)
                Assert.False(a.Box.Overlaps(LabelBox.AroundCircle(c.X, c.Y, CanvasLabelLayout.MarkerPixels)), $"{moment}: '{a.Text}' covers the centre of mass")
            End If
        Next
        Return labels.Count
    End Function

    <Fact>
    Public Sub NewtonsCradle_WithItsImpulses_NoLabelCoversAnother()
        Dim h = Lesson("newtons-cradle.json")
        h.P.SetShowImpulses(True)
        Dim most = 0, impulses = 0
        For frame = 1 To 240
            h.P.Tick(1 / 60.0)
            If frame Mod 4 = 0 Then
                most = Math.Max(most, CheckLabels(h, "frame " & frame))
                impulses = Math.Max(impulses, h.P.LayOutLabels(AddressOf Measure, 800, 500).Where(Function(l) l.Kind = CanvasLabelKind.Impulse).Count())
            End If
        Next
        Assert.True(impulses >= 1, "no impulse was labelled")
        Assert.True(most >= h.P.World.Movables.Count, "fewer labels than balls")
    End Sub

    <Fact>
    Public Sub PoolBreak_WithEveryView_NoLabelCoversAnother_AndThePanelIsBesideTheTable()
        Dim h = Lesson("pool-break.json")
        h.P.SetShowCentreOfMass(True)
        h.P.SetShowTotalMomentum(True)
        h.P.SetShowMomentaDiagram(True)
        h.P.SetShowImpulses(True)
        h.P.SetShowTraces(True)
        ' The panel has its own column: the container ends left of it.
        Dim right = h.P.View.ToScreen(New Vector(h.P.World.Width, 0)).X
        Assert.True(right <= 800 - h.P.MomentumPanelPixels, $"the container reaches {right} px, into the panel's column from {800 - h.P.MomentumPanelPixels} px")
        Dim kinds As New HashSet(Of CanvasLabelKind)
        For frame = 1 To 180
            h.P.Tick(1 / 60.0)
            If frame Mod 3 = 0 Then
                CheckLabels(h, "frame " & frame)
                For Each l In h.P.LayOutLabels(AddressOf Measure, 800, 500)
                    kinds.Add(l.Kind)
                Next
            End If
        Next
        Assert.Contains(CanvasLabelKind.CentreOfMass, kinds)
        Assert.Contains(CanvasLabelKind.TotalMomentum, kinds)
        Assert.Contains(CanvasLabelKind.Body, kinds)
        Assert.Contains(CanvasLabelKind.Impulse, kinds)
    End Sub

    ''' <summary>
    ''' A fixed ball's id is placed beside it, not over the cross in its middle that marks it fixed;
    ''' a moving ball as big has its id inside it.
    ''' </summary>
    <Fact>
    Public Sub AFixedBallsId_IsBesideIt_NotOverItsCross()
        Dim h As New PresenterHarness()
        h.P.World.Add(Circle.CreateFixed(New Vector(4, 1.5), 0.5, "peg"))
        h.P.World.Add(New Circle(New Vector(2, 3.5), 0.5, 1.0, Vector.Zero, "ball"))
        Dim labels = h.P.LayOutLabels(AddressOf Measure, 800, 500)
        Dim peg = Assert.Single(labels, Function(l) l.Text = "peg")
        Dim pegBox = CanvasLabelLayout.ScreenBox(peg.Body, h.P.View, 1.0)
        Assert.True(pegBox.Width > 40, $"the fixed ball is only {pegBox.Width} px across: too small to test")
        Assert.False(peg.Inside, "the fixed ball's id is inside it, over its cross")
        Assert.False(peg.Box.Overlaps(pegBox), "the fixed ball's id covers the ball")
        Assert.True(Assert.Single(labels, Function(l) l.Text = "ball").Inside, "the moving ball's id is not inside it")
        CheckLabels(h, "a fixed and a moving ball")
    End Sub

    <Fact>
    Public Sub ALabelWithNoRoom_IsLeftOut_NotDrawnOverSomething()
        Dim placer As New LabelPlacer(New LabelBox(0, 0, 100, 100))
        placer.AddObstacle(New LabelBox(0, 0, 100, 100))
        Assert.Null(placer.Place(LabelPlacer.Around(New LabelBox(40, 40, 20, 20), 30, 16, 3)))
        Dim free As New LabelPlacer(New LabelBox(0, 0, 100, 100))
        Dim first = free.Place(LabelPlacer.Around(New LabelBox(40, 40, 20, 20), 30, 16, 3))
        Dim second = free.Place(LabelPlacer.Around(New LabelBox(40, 40, 20, 20), 30, 16, 3))
        Assert.True(first.HasValue AndAlso second.HasValue)
        Assert.False(first.Value.Overlaps(second.Value))
    End Sub
End Class
