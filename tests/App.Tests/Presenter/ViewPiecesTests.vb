Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The transform, the scale bar, colours and help texts.</summary>
Public Class ViewPiecesTests
    <Fact>
    Public Sub ViewTransform_FlipsY_AndRoundTrips()
        Dim v = ViewTransform.Fit(8, 5, 820, 520, 10)
        Dim floorLeft = v.ToScreen(New Vector(0, 0))
        Dim topLeft = v.ToScreen(New Vector(0, 5))
        Assert.True(topLeft.Y < floorLeft.Y, "y up in the model is up on the screen")
        Assert.Equal(100.0, v.Scale, 6)
        Dim back = v.ToWorld(floorLeft.X + 150, floorLeft.Y - 50)
        Assert.Equal(1.5, back.X, 9)
        Assert.Equal(0.5, back.Y, 9)
    End Sub

    <Theory>
    <InlineData(100.0, 160.0, 1.0, "1 m")>
    <InlineData(30.0, 160.0, 5.0, "5 m")>
    <InlineData(1000.0, 160.0, 0.1, "10 cm")>
    Public Sub ScaleBar_ChoosesARoundLength(pxPerMetre As Double, maxPx As Double, metres As Double, label As String)
        Dim bar = ScaleBar.Choose(pxPerMetre, maxPx)
        Assert.Equal(metres, bar.Metres, 9)
        Assert.Equal(label, bar.Label)
        Assert.True(bar.Pixels <= maxPx)
    End Sub

    <Fact>
    Public Sub RandomColours_AlwaysShowOnBothCanvases()
        Dim colours As New BodyColours(7)
        Dim seen As New HashSet(Of String)
        For k = 1 To 500
            Dim c = colours.NextColour()
            Dim rgb = BodyColours.Parse(c, -1)
            Assert.True(BodyColours.ContrastRatio(rgb, Theme.Light.Background) >= 3, c)
            Assert.True(BodyColours.ContrastRatio(rgb, Theme.Dark.Background) >= 3, c)
            seen.Add(c)
        Next
        Assert.True(seen.Count > 300, "colours vary")
    End Sub

    <Fact>
    Public Sub Colours_HsvAndHex()
        Assert.Equal(&HFF0000, BodyColours.FromHsv(0, 1, 1))
        Assert.Equal(&HFF00, BodyColours.FromHsv(120, 1, 1))
        Assert.Equal("#00ff00", BodyColours.ToHex(&HFF00))
        Assert.Equal(&H123ABC, BodyColours.Parse("#123abc", 0))
        Assert.Equal(-1, BodyColours.Parse("red", -1))
        Assert.Equal(21.0, BodyColours.ContrastRatio(0, &HFFFFFF), 6)
    End Sub

    <Fact>
    Public Sub Tutorial_CoversAddingRemovingManipulatingControlsAndLimits()
        Dim all = String.Join(vbLf, HelpTexts.Tutorial.Select(Function(t) t.Title & vbLf & t.Text))
        For Each word In {"Add circle", "Delete mode", "RIGHT mouse button", "LEFT mouse button", "Pause", "Speed", "Restitution", "Limits of the model", "Please spawn your current object first!"}
            Assert.Contains(word, all, StringComparison.Ordinal)
        Next
    End Sub

    <Fact>
    Public Sub Maths_CoversImpulseParabolaTimeOfImpactRestingAndFma()
        Dim all = String.Join(vbLf, HelpTexts.Maths.Select(Function(t) t.Title & vbLf & t.Text))
        For Each word In {"j = −(1 + e) u / (1/m_A + 1/m_B)", "y(t) = y₀ + v_y t − ½ g t²", "(w·w) t² + 2 (d₀·w) t + (d₀·d₀ − R²) = 0", "resting", "Δv = J / m"}
            Assert.Contains(word, all, StringComparison.Ordinal)
        Next
    End Sub
End Class
