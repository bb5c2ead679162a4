Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>The window on the screens a classroom has: small laptops, projectors, high-DPI screens.</summary>
<Collection(RealWindow.Name)>
Public Class LayoutGuiTests
    Private Shared ReadOnly TotalsItems As String() = {"t", "Σp", "|Σp|", "ΣKE", "ΣPE", "KE", "collisions:"}
    Private Shared ReadOnly LineBreak As String() = {" / "}
    Private Shared ReadOnly ItemGap As String() = {"     "}

    <GuiTheory>
    <InlineData("1024x768x24", 0, "layout-1024x768")>
    <InlineData("1280x720x24", 0, "layout-1280x720")>
    <InlineData("2560x1600x24", 192, "layout-192dpi")>
    Public Sub EveryControlIsOnScreen_WholeAndReadable(screen As String, dpi As Integer, shotName As String)
        Dim size = screen.Split("x"c)
        Dim screenW = Integer.Parse(size(0), CultureInfo.InvariantCulture), screenH = Integer.Parse(size(1), CultureInfo.InvariantCulture)
        Using app As New AppDriver(New XSessionOptions With {.Screen = screen, .Dpi = dpi})
            Dim window = app.LastMatch("^window (-?\d+) (-?\d+) (\d+) (\d+)$")
            Dim wx = Int(window.Groups(1).Value), wy = Int(window.Groups(2).Value), ww = Int(window.Groups(3).Value), wh = Int(window.Groups(4).Value)
            Assert.True(wx >= 0 AndAlso wy >= 0 AndAlso wx + ww <= screenW AndAlso wy + wh <= screenH, $"the window ({wx}, {wy}, {ww} × {wh}) does not fit the {screenW} × {screenH} screen")
            Dim side = app.Control("side")
            Dim panel As New List(Of (Name As String, R As (X As Integer, Y As Integer, W As Integer, H As Integer)))
            Dim below As New List(Of String)
            For Each line In app.LastLayout()
                Dim m = Regex.Match(line, "^control (\S+) (-?\d+) (-?\d+) (\d+) (\d+) (fits|cut)$")
                Dim name = m.Groups(1).Value
                Dim r = (X:=Int(m.Groups(2).Value), Y:=Int(m.Groups(3).Value), W:=Int(m.Groups(4).Value), H:=Int(m.Groups(5).Value))
                ' A side panel too full for the screen scrolls: what is below its visible part is reached by scrolling (checked below).
                If name <> "side" AndAlso r.X >= side.X AndAlso r.Y >= side.Y AndAlso r.Y + r.H > side.Y + side.H Then
                    below.Add(name)
                    Continue For
                End If
                Assert.True(r.X >= wx AndAlso r.Y >= wy AndAlso r.X + r.W <= wx + ww AndAlso r.Y + r.H <= wy + wh, $"{name} at ({r.X}, {r.Y}, {r.W} × {r.H}) is outside the window")
                Assert.True(m.Groups(6).Value = "fits", $"{name}'s caption is cut off ({r.W} px wide)")
                If name <> "side" AndAlso r.X >= side.X Then
                    ' On the side panel: in its visible part, with no scrolling needed.
                    Assert.True(r.Y >= side.Y AndAlso r.Y + r.H <= side.Y + side.H AndAlso r.X + r.W <= side.X + side.W, $"{name} is off the visible side panel")
                    panel.Add((name, r))
                End If
            Next
            For i = 0 To panel.Count - 1
                For j = i + 1 To panel.Count - 1
                    Dim a = panel(i).R, b = panel(j).R
                    Dim apart = a.X + a.W <= b.X OrElse b.X + b.W <= a.X OrElse a.Y + a.H <= b.Y OrElse b.Y + b.H <= a.Y
                    Assert.True(apart, $"{panel(i).Name} and {panel(j).Name} overlap")
                Next
            Next
            If below.Count > 0 Then
                ' Mono sends the mouse wheel to the focused control, which passes it to its panel: a box on
                ' the panel takes the focus first (ticked and cleared again, so nothing changes).
                app.ClickAndWait("fixed", "^inputs ")
                app.ClickAndWait("fixed", "^inputs ")
            End If
            For Each name In below
                Dim r = app.ScrollIntoView(name)
                side = app.Control("side")
                Assert.True(r.Y >= side.Y AndAlso r.Y + r.H <= side.Y + side.H, $"{name} cannot be scrolled into view ({r.Y}, panel {side.Y} to {side.Y + side.H})")
                Assert.True(app.LastLayout().Any(Function(l) l.StartsWith("control " & name & " ", StringComparison.Ordinal) AndAlso l.EndsWith(" fits", StringComparison.Ordinal)), $"{name}'s caption is cut off")
            Next
            If dpi > 0 Then
                app.WaitFor("^dpi " & dpi & " ")
                Dim pause = app.Control("pause")
                Assert.True(pause.H >= 2 * 26, $"at {dpi} dpi the buttons are {pause.H} px high: not scaled")
            End If
            ' The totals line breaks only between its items, never inside "18.6 J".
            Dim from = app.Mark()
            app.ClickAndWait("pause", "^paused")
            Dim totals = app.WaitFor("^totals (.*)$", skip:=from).Groups(1).Value
            For Each line In totals.Split(LineBreak, StringSplitOptions.None)
                For Each item In line.Split(ItemGap, StringSplitOptions.RemoveEmptyEntries)
                    Assert.DoesNotContain(" ", item, StringComparison.Ordinal)
                    Assert.Contains(item.Split(Presentation.Units.Nbsp)(0), TotalsItems)
                Next
            Next
            Thread.Sleep(300)
            app.X.Shoot(shotName)
        End Using
    End Sub

    <GuiFact>
    Public Sub TheSidePanel_StaysWhereItWasScrolled_WhenAToggleIsClicked()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x720x24"})
            Dim from = app.Mark()
            app.Click("large-fonts")
            app.WaitFor("^large fonts on$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            app.ReadLayout()
            Dim side = app.Control("side")
            Dim top = app.Control("arrows").Y
            ' With large fonts at 720 px the panel scrolls: scroll it with the wheel.
            from = app.Mark()
            app.MoveTo(side.X + side.W \ 2, side.Y + side.H \ 2)
            For k = 1 To 8
                app.X.XDo("click", "5")
                Thread.Sleep(100)
            Next
            app.WaitFor("^ready$", skip:=from)
            Thread.Sleep(300)
            app.ReadLayout()
            Dim scrolled = app.Control("arrows").Y
            Assert.True(scrolled < top - 50, $"the panel did not scroll ({top} → {scrolled})")
            ' Each toggle lays the window out again: the panel must not jump back to the top.
            For Each toggle In {"arrows", "high-contrast", "arrows"}
                from = app.Mark()
                app.Click(toggle)
                app.WaitFor("^ready$", skip:=from)
                app.ReadLayout()
                Assert.Equal(scrolled, app.Control("arrows").Y)
            Next
            app.X.Shoot("scrolled-panel")
        End Using
    End Sub

    Private Shared Function Int(text As String) As Integer
        Return Integer.Parse(text, CultureInfo.InvariantCulture)
    End Function
End Class
