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

    Private Shared ReadOnly SideTextBoxes As String() = {"friction", "static-friction", "radius", "mass", "rect-width", "rect-height", "sides", "angle", "stiffness", "box-width", "box-height"}

    Private Shared ReadOnly Sized As String() = {"canvas", "totals", "tabs", "side", "message", "graph"}

    ''' <summary>The rectangles of the last layout the app printed, by control name (table cells left out: they follow the rows).</summary>
    Private Shared Function Rects(app As AppDriver) As Dictionary(Of String, (X As Integer, Y As Integer, W As Integer, H As Integer))
        Dim result As New Dictionary(Of String, (X As Integer, Y As Integer, W As Integer, H As Integer))(StringComparer.Ordinal)
        For Each line In app.LastLayout()
            Dim m = Regex.Match(line, "^control (\S+) (-?\d+) (-?\d+) (\d+) (\d+) (fits|cut)$")
            If Not m.Success OrElse m.Groups(1).Value.StartsWith("cell-", StringComparison.Ordinal) Then Continue For
            result(m.Groups(1).Value) = (Int(m.Groups(2).Value), Int(m.Groups(3).Value), Int(m.Groups(4).Value), Int(m.Groups(5).Value))
        Next
        Return result
    End Function

    ''' <summary>The panel's scroll, px, at the last layout.</summary>
    Private Shared Function Scrolled(app As AppDriver) As Integer
        Return Int(app.LastMatch("^text line \d+ px, scroll bar \d+ px, panel overflow \d+ px, scrolled (\d+) px$").Groups(1).Value)
    End Function

    ''' <summary>
    ''' The window on the screens a classroom has: small laptops, projectors at 1280 × 800 with large
    ''' fonts and high contrast, 144- and 192-dpi screens. Every control is on the screen, its caption
    ''' whole (a button's from side to side and from top to bottom), at least as tall as a line of text (a check box's box and a slider's thumb grow with the
    ''' text too); with normal fonts every control of the side panel shows without scrolling, and with
    ''' large fonts any below the fold is reached with the wheel, in one page at most. Then messages of every length come
    ''' and go while time runs (the totals changing): no control moves by a pixel.
    ''' </summary>
    <GuiTheory>
    <InlineData("1024x768x24", 0, False, False, "layout-1024x768")>
    <InlineData("1280x720x24", 0, False, False, "layout-1280x720")>
    <InlineData("1024x768x24", 0, True, True, "layout-1024x768-large-contrast")>
    <InlineData("1280x800x24", 0, True, True, "layout-1280x800-large-contrast")>
    <InlineData("1920x1200x24", 144, False, False, "layout-144dpi")>
    <InlineData("2560x1600x24", 192, False, False, "layout-192dpi")>
    <InlineData("2560x1600x24", 192, True, True, "layout-192dpi-large-contrast")>
    Public Sub EveryControlIsOnScreen_AsLargeAsItsText_AndNothingMovesWhenAMessageChanges(screen As String, dpi As Integer, large As Boolean, contrast As Boolean, shotName As String)
        Dim size = screen.Split("x"c)
        Dim screenW = Integer.Parse(size(0), CultureInfo.InvariantCulture), screenH = Integer.Parse(size(1), CultureInfo.InvariantCulture)
        Using app As New AppDriver(New XSessionOptions With {.Screen = screen, .Dpi = dpi})
            If dpi > 0 Then app.WaitFor("^dpi " & dpi & " ")
            For Each toggle In {(large, "large-fonts", "large fonts"), (contrast, "high-contrast", "high contrast")}
                If Not toggle.Item1 Then Continue For
                Dim mark = app.Mark()
                app.Click(toggle.Item2)
                app.WaitFor("^" & toggle.Item3 & " on$", skip:=mark)
                app.WaitFor("^ready$", skip:=mark)
            Next
            Dim window = app.LastMatch("^window (-?\d+) (-?\d+) (\d+) (\d+)$")
            Dim wx = Int(window.Groups(1).Value), wy = Int(window.Groups(2).Value), ww = Int(window.Groups(3).Value), wh = Int(window.Groups(4).Value)
            Assert.True(wx >= 0 AndAlso wy >= 0 AndAlso wx + ww <= screenW AndAlso wy + wh <= screenH, $"the window ({wx}, {wy}, {ww} × {wh}) does not fit the {screenW} × {screenH} screen")
            Dim line = Int(app.LastMatch("^text line (\d+) px").Groups(1).Value)
            Dim overflow = Int(app.LastMatch("panel overflow (\d+) px").Groups(1).Value)
            If Not large Then Assert.True(overflow = 0, $"with normal fonts the side panel needs {overflow} px more than the {screen} screen has")
            Dim side = app.Control("side")
            ' With large fonts the panel may scroll, but by at most one page: every control is in view
            ' either at the top or after one scroll of the panel's own height, at 192 dpi too (the rows
            ' are as tall as the text drawn, not as the font height Mono reports under Xft.dpi).
            If large Then Assert.True(overflow <= side.H, $"with large fonts the side panel needs {overflow} px more than its {side.H} px: more than one scroll")
            Dim panel As New List(Of (Name As String, R As (X As Integer, Y As Integer, W As Integer, H As Integer)))
            Dim below As New List(Of String)
            For Each line2 In app.LastLayout()
                Dim m = Regex.Match(line2, "^control (\S+) (-?\d+) (-?\d+) (\d+) (\d+) (fits|cut)$")
                Dim name = m.Groups(1).Value
                Dim r = (X:=Int(m.Groups(2).Value), Y:=Int(m.Groups(3).Value), W:=Int(m.Groups(4).Value), H:=Int(m.Groups(5).Value))
                ' A table's cells are where its columns put them: a wide table scrolls sideways, and the cells past its edge are hidden, not on the panel.
                If name.StartsWith("cell-", StringComparison.Ordinal) Then Continue For
                ' Scrolled out of the panel's visible part (above or below): reached by scrolling, checked below.
                If name <> "side" AndAlso r.X >= side.X AndAlso (r.Y < side.Y OrElse r.Y + r.H > side.Y + side.H) Then
                    below.Add(name)
                    Continue For
                End If
                Assert.True(r.X >= wx AndAlso r.Y >= wy AndAlso r.X + r.W <= wx + ww AndAlso r.Y + r.H <= wy + wh, $"{name} at ({r.X}, {r.Y}, {r.W} × {r.H}) is outside the window")
                Assert.True(m.Groups(6).Value = "fits", $"{name}'s caption is cut off ({r.W} px wide)")
                ' Every control is at least as tall as a line of its text (a table's cells follow its rows).
                If Not Sized.Contains(name) AndAlso Not name.StartsWith("cell-", StringComparison.Ordinal) Then
                    Assert.True(r.H >= line, $"{name} is {r.H} px high, less than a line of text ({line} px)")
                End If
                If name <> "side" AndAlso r.X >= side.X Then
                    Assert.True(r.Y >= side.Y AndAlso r.Y + r.H <= side.Y + side.H AndAlso r.X + r.W <= side.X + side.W, $"{name} is off the visible side panel")
                    panel.Add((name, r))
                End If
            Next
            ' A check box's box and a slider's thumb grow with the text, not only the control around them.
            Dim all = app.Lines()
            Dim lastReady = Array.LastIndexOf(all, "ready")
            Dim previousReady = Array.LastIndexOf(all, "ready", lastReady - 1)
            Dim block = all.Skip(previousReady + 1).Take(lastReady - previousReady - 1)
            Dim parts = block.Select(Function(l) Regex.Match(l, "^part (\S+) (box|thumb) (\d+) (\d+)$")).Where(Function(x) x.Success).ToList()
            Assert.True(parts.Count >= 10, "the layout names no check box or slider parts")
            For Each m In parts
                Dim w = Int(m.Groups(3).Value), h = Int(m.Groups(4).Value)
                If m.Groups(2).Value = "box" Then
                    Assert.True(w >= 0.6 * line, $"{m.Groups(1).Value}'s box is {w} px, beside text {line} px high")
                Else
                    Assert.True(w >= 0.45 * line AndAlso h >= 0.6 * line, $"{m.Groups(1).Value}'s thumb is {w} × {h} px, beside text {line} px high")
                End If
            Next
            Assert.True(CaptionsWholeTopToBottom(block) >= 20, "the layout names no button captions")
            ' A text box of the side panel is a line of text and a margin high, no more: the text, written
            ' at the box's top, then sits in its middle (not at the top of a box twice its height).
            Dim laidOut = Rects(app)
            For Each name In SideTextBoxes
                Dim r = laidOut(name)
                Assert.True(r.H <= line + line \ 2, $"the {name} box is {r.H} px high for a line of {line} px: its text sits at the top, not in the middle")
            Next
            For i = 0 To panel.Count - 1
                For j = i + 1 To panel.Count - 1
                    Dim a = panel(i).R, b = panel(j).R
                    Dim apart = a.X + a.W <= b.X OrElse b.X + b.W <= a.X OrElse a.Y + a.H <= b.Y OrElse b.Y + b.H <= a.Y
                    Assert.True(apart, $"{panel(i).Name} and {panel(j).Name} overlap")
                Next
            Next
            For Each name In below
                Dim r = app.ScrollIntoView(name)
                side = app.Control("side")
                Assert.True(r.Y >= side.Y AndAlso r.Y + r.H <= side.Y + side.H, $"{name} cannot be scrolled into view ({r.Y}, panel {side.Y} to {side.Y + side.H})")
                Assert.True(app.LastLayout().Any(Function(l) l.StartsWith("control " & name & " ", StringComparison.Ordinal) AndAlso l.EndsWith(" fits", StringComparison.Ordinal)), $"{name}'s caption is cut off")
            Next

            ' Messages of every length, time running: every control stays where it was (the side panel's
            ' controls where they were in the panel, whatever it is scrolled to).
            Dim before = Rects(app)
            Dim beforeScroll = Scrolled(app)
            Dim longest = 0
            For Each act In {"delete-mode", "delete-mode", "long", "delete-mode", "delete-mode"}
                Dim mark = app.Mark()
                If act = "long" Then
                    app.TypeInto("box-width", "0.5.5.5.5.5.5.5.5.5.5.5.5.5.5.5.5.5.5.5")
                    app.TypeInto("box-height", "4.4.4.4.4.4.4.4.4.4.4.4.4.4.4.4.4.4.4.4")
                    mark = app.Mark()
                    app.Click("resize")
                Else
                    app.Click(act)
                End If
                Dim shown = app.WaitFor("^message shown (\d+) px, needs (\d+) px", skip:=mark)
                app.WaitFor("^ready$", skip:=mark)
                longest = Math.Max(longest, Int(shown.Groups(2).Value))
                Dim after = Rects(app)
                Dim shift = Scrolled(app) - beforeScroll
                For Each kv In before
                    Dim now As (X As Integer, Y As Integer, W As Integer, H As Integer) = Nothing
                    If Not after.TryGetValue(kv.Key, now) Then Continue For
                    Dim onPanel = kv.Value.X >= side.X AndAlso kv.Key <> "side"
                    Dim expectedY = kv.Value.Y - If(onPanel, shift, 0)
                    Assert.True(now.X = kv.Value.X AndAlso now.Y = expectedY AndAlso now.W = kv.Value.W AndAlso now.H = kv.Value.H,
                                $"{kv.Key} moved from ({kv.Value.X}, {expectedY}, {kv.Value.W} × {kv.Value.H}) to ({now.X}, {now.Y}, {now.W} × {now.H}) after '{act}'")
                Next
            Next
            Dim area = before("message")
            Assert.True(longest > area.H, $"the longest message needed {longest} px, no more than the area's {area.H} px: it did not test scrolling")
            app.LastMatch("^message shown \d+ px, needs \d+ px, scrolls$")

            ' The totals line breaks only between its items, never inside "18.6 J".
            Dim from = app.Mark()
            app.ClickAndWait("pause", "^paused")
            Dim totals = app.WaitFor("^totals (.*)$", skip:=from).Groups(1).Value
            For Each totalsLine In totals.Split(LineBreak, StringSplitOptions.None)
                For Each item In totalsLine.Split(ItemGap, StringSplitOptions.RemoveEmptyEntries)
                    Assert.DoesNotContain(" ", item, StringComparison.Ordinal)
                    Assert.Contains(item.Split(Presentation.Units.Nbsp)(0), TotalsItems)
                Next
            Next
            ' The buttons of the Graphs and Forces pages, laid out when their tab opens, are whole from top to bottom too.
            For Each pageName In {"Graphs", "Forces"}
                from = app.Mark()
                app.Click("tab-" & pageName.ToLowerInvariant())
                app.WaitFor("^tab " & pageName & "$", skip:=from)
                app.WaitFor("^ready$", skip:=from)
                Dim all2 = app.Lines()
                Dim ready2 = Array.LastIndexOf(all2, "ready")
                Dim previous2 = Array.LastIndexOf(all2, "ready", ready2 - 1)
                Dim onPage = If(pageName = "Graphs", "graph-window", "forces-set-air")
                Dim block2 = all2.Skip(previous2 + 1).Take(ready2 - previous2 - 1).ToList()
                Assert.True(block2.Any(Function(l) l.StartsWith("caption " & onPage & " ", StringComparison.Ordinal)), $"the {pageName} page's buttons were not laid out")
                CaptionsWholeTopToBottom(block2)
                If pageName = "Forces" Then ForcesPageScalesWithTheText(block2, line)
            Next
            Thread.Sleep(300)
            app.X.Shoot(shotName)
        End Using
    End Sub

    ''' <summary>
    ''' Every button's caption in a layout is whole from top to bottom: the height it is placed by (the
    ''' text's when it is aligned to the top, the font's as the toolkit reports it when centred), with the
    ''' button's padding and its edge (a bevel of 2 px and a focus margin of 1, top and bottom), fits
    ''' inside the button. Returns how many captions it checked.
    ''' </summary>
    Private Shared Function CaptionsWholeTopToBottom(block As IEnumerable(Of String)) As Integer
        Dim captions = block.Select(Function(l) Regex.Match(l, "^caption (\S+) client (\d+) padding (\d+) (\d+) line (\d+) placed (\d+)$")).Where(Function(x) x.Success).ToList()
        For Each m In captions
            Dim client = Int(m.Groups(2).Value), padTop = Int(m.Groups(3).Value), padBottom = Int(m.Groups(4).Value), placed = Int(m.Groups(6).Value)
            Assert.True(padTop + placed + padBottom + 2 * 3 <= client,
                        $"{m.Groups(1).Value}'s caption is cut from top to bottom: placed by {placed} px, with padding {padTop} + {padBottom} and its edges, in a button {client} px high")
        Next
        Return captions.Count
    End Function

    ''' <summary>The text boxes and the body's drop-down of the Forces page, as the side panel's: a line of text and a margin high.</summary>
    Private Shared ReadOnly ForcesBoxes As String() = {"forces-air-density", "forces-cd", "forces-b", "forces-body"}

    ''' <summary>
    ''' The Forces page's controls in a layout grow with the text as the side panel's do: each at least
    ''' a line of text high, its two check boxes' boxes as large as the side panel's (not the toolkit's
    ''' 13 px at every DPI), and its text boxes and drop-down a line and a margin high (at most one and
    ''' a half lines: the text in their middle, not at the top of a box twice as tall).
    ''' </summary>
    Private Shared Sub ForcesPageScalesWithTheText(block As IEnumerable(Of String), line As Integer)
        Dim rects As New Dictionary(Of String, (W As Integer, H As Integer))(StringComparer.Ordinal)
        Dim boxes As New Dictionary(Of String, Integer)(StringComparer.Ordinal)
        For Each l In block
            Dim m = Regex.Match(l, "^control (forces-\S+) -?\d+ -?\d+ (\d+) (\d+) (fits|cut)$")
            If m.Success Then rects(m.Groups(1).Value) = (Int(m.Groups(2).Value), Int(m.Groups(3).Value))
            m = Regex.Match(l, "^part (forces-\S+) box (\d+) \d+$")
            If m.Success Then boxes(m.Groups(1).Value) = Int(m.Groups(2).Value)
        Next
        Assert.True(rects.Count >= 10, "the layout names no controls of the Forces page")
        For Each kv In rects
            If kv.Key = "forces-list" OrElse kv.Key = "forces-sum" Then Continue For
            Assert.True(kv.Value.H >= line, $"{kv.Key} is {kv.Value.H} px high, less than a line of text ({line} px)")
        Next
        For Each name In {"forces-show", "forces-air"}
            Dim side As Integer
            Assert.True(boxes.TryGetValue(name, side), $"{name}'s box is the toolkit's, drawn 13 px square at every DPI, beside text {line} px high")
            Assert.True(side >= 0.6 * line, $"{name}'s box is {side} px, beside text {line} px high")
        Next
        For Each name In ForcesBoxes
            Dim r = rects(name)
            Assert.True(r.H <= line + line \ 2, $"the {name} box is {r.H} px high for a line of {line} px: its text sits at the top, not in the middle")
        Next
    End Sub

    ''' <summary>
    ''' At 144 and 192 dpi a one-line text box shows its figures whole once text is typed into it or set
    ''' by the app: its view of its line stays at the top (Mono scrolls a box to show the whole of a line
    ''' it lays out twice as tall as the figures, which leaves only their bottom edge in view). The side
    ''' panel's radius box after typing, and the Forces page's C_d and b boxes when the page fills them.
    ''' </summary>
    <GuiTheory>
    <InlineData("1920x1200x24", 144)>
    <InlineData("2560x1600x24", 192)>
    Public Sub AOneLineTextBox_ShowsItsFiguresWhole_AfterTextIsTypedOrSet(screen As String, dpi As Integer)
        Using app As New AppDriver(New XSessionOptions With {.Screen = screen, .Dpi = dpi})
            app.WaitFor("^dpi " & dpi & " ")
            app.WaitFor("^ready$")
            Dim from = app.Mark()
            app.TypeInto("radius", "0.375")
            Dim typed = app.WaitFor("^box Radius view top (-?\d+) px \[0\.375\]$", skip:=from)
            Assert.True(Int(typed.Groups(1).Value) = 0, $"after typing at {dpi} dpi the radius box's view is scrolled {typed.Groups(1).Value} px down its line: only the bottom of the figures shows")
            from = app.Mark()
            app.Click("tab-forces")
            app.WaitFor("^tab Forces$", skip:=from)
            For Each name In {"forces-cd", "forces-b"}
                Dim filled = app.WaitFor("^box " & name & " view top (-?\d+) px \[.+\]$", skip:=from)
                Assert.True(Int(filled.Groups(1).Value) = 0, $"once the Forces page filled it at {dpi} dpi, the {name} box's view is scrolled {filled.Groups(1).Value} px down its line")
            Next
            app.X.Shoot("one-line-boxes-" & dpi & "dpi")
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
            ' With large fonts at 720 px the panel scrolls: scroll it with the wheel, over the panel, with
            ' the keyboard's focus wherever it is (Mono would send the wheel to the focused control).
            from = app.Mark()
            app.MoveTo(side.X + side.W \ 2, side.Y + side.H \ 2)
            For k = 1 To 8
                app.X.XDo("click", "5")
            Next
            ' Each turn is acknowledged once the app has handled it: wait for all eight, not for time.
            app.WaitForCount("^wheel side ", 8, from)
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

    ''' <summary>
    ''' The Bodies table with every kind of body (a 12-sided polygon of small sides, a ramp, boxes),
    ''' with large fonts: every column is as wide as its header and its values need, the Size
    ''' column too, and the tables have room for more than two rows.
    ''' </summary>
    <GuiFact>
    Public Sub TheBodiesTable_GivesEveryColumnRoomForItsValues_WithLargeFonts()
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-columns-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Dim scene = IO.Path.Combine(folder, "kinds.json")
        Dim corners = String.Join(", ", Enumerable.Range(0, 12).Select(Function(k) "[" & (4 + 0.0123 * Math.Cos(k * Math.PI / 6)).ToString("R", CultureInfo.InvariantCulture) & ", " &
                                                                                          (3 + 0.0123 * Math.Sin(k * Math.PI / 6)).ToString("R", CultureInfo.InvariantCulture) & "]"))
        IO.File.WriteAllText(scene, "{""format"":""physics-scene/1"",""world"":{""width"":8,""height"":5,""gravity"":0},""bodies"":[" &
            "{""id"":""dodecagon"",""type"":""polygon"",""vertices"":[" & corners & "],""mass"":1.0}," &
            "{""id"":""slope"",""type"":""segment"",""x1"":1,""y1"":0.5,""x2"":3.123456,""y2"":1.5}," &
            "{""id"":""crate"",""type"":""rectangle"",""x"":5,""y"":0,""width"":1.23456,""height"":0.987654,""fixed"":false,""mass"":2.5,""vx"":-1.5}," &
            "{""id"":""table"",""type"":""rectangle"",""x"":6.5,""y"":0,""width"":1,""height"":0.5,""fixed"":true}," &
            "{""id"":""ball"",""type"":""circle"",""x"":2,""y"":3,""radius"":0.25,""mass"":1,""vx"":-12.345678}]}")
        Try
            Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x800x24"}, scene)
                app.WaitFor("^opened kinds.json: 5 bodies")
                Dim from = app.Mark()
                app.Click("large-fonts")
                app.WaitFor("^large fonts on$", skip:=from)
                app.WaitFor("^ready$", skip:=from)
                from = app.Mark()
                app.Click("tab-bodies")
                app.WaitFor("^tab Bodies$", skip:=from)
                app.WaitFor("^row Bodies 4: ", skip:=from)
                Thread.Sleep(700)
                Dim widths As New Dictionary(Of Integer, (Width As Integer, Needs As Integer))
                For Each line In app.Lines()
                    Dim m = Regex.Match(line, "^column Bodies (\d+) width (\d+) needs (\d+)$")
                    If m.Success Then widths(Int(m.Groups(1).Value)) = (Int(m.Groups(2).Value), Int(m.Groups(3).Value))
                Next
                Assert.Equal(12, widths.Count) ' ten columns, then the surface's μk and μs
                For Each kv In widths
                    Assert.True(kv.Value.Width >= kv.Value.Needs, $"column {kv.Key} of the Bodies table is {kv.Value.Width} px wide; its header and values need {kv.Value.Needs} px")
                Next
                ' The polygon is named by its sides, its Size is its width × height: "0.0246 × 0.0238".
                Dim size = app.LastMatch("^row Bodies \d+: dodecagon \| #[0-9a-f]{6} \| dodecagon \| .* \| ([^|]+ × [^|]+) \| [^|]+ \| [^|]+$").Groups(1).Value
                Assert.StartsWith("0.02", size, StringComparison.Ordinal)
                app.X.Shoot("bodies-table-large")
            End Using
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub

    ''' <summary>
    ''' Every column of a table shows without a sideways scroll: the last column's right edge lies
    ''' within the list's visible width, as the app laid it out for the scene it opened, after time
    ''' has run. The Bodies table on a 1280-px-wide screen with normal fonts, for the scene the app
    ''' starts with (balls, a fixed ball and a fixed rectangle), for one with every kind of body but
    ''' polygons (boxes with their own friction among them, the μk and μs columns at its right end),
    ''' for one with a polygon (named by its sides, "pentagon"), and for one with a fixed
    ''' quadrilateral (the longest kind, "fixed quadrilateral"); the Circles table at 192 dpi with
    ''' large fonts.
    ''' </summary>
    <GuiTheory>
    <InlineData("1280x800x24", 0, False, "", "Bodies")>
    <InlineData("1280x720x24", 0, False, "", "Bodies")>
    <InlineData("1280x800x24", 0, False, "kinds", "Bodies")>
    <InlineData("1280x720x24", 0, False, "kinds", "Bodies")>
    <InlineData("1280x800x24", 0, False, "polygon", "Bodies")>
    <InlineData("1280x720x24", 0, False, "polygon", "Bodies")>
    <InlineData("1280x800x24", 0, False, "quadrilateral", "Bodies")>
    <InlineData("1280x720x24", 0, False, "quadrilateral", "Bodies")>
    <InlineData("2560x1600x24", 192, True, "", "Circles")>
    <InlineData("2560x1600x24", 192, True, "kinds", "Bodies")>
    <InlineData("2560x1600x24", 192, True, "polygon", "Bodies")>
    <InlineData("2560x1600x24", 192, True, "quadrilateral", "Bodies")>
    <InlineData("2560x1600x24", 192, True, "kinds", "Rectangles")>
    <InlineData("2560x1600x24", 192, True, "kinds", "Links")>
    Public Sub TheTable_ShowsEveryColumn_WithoutASidewaysScroll(screen As String, dpi As Integer, large As Boolean, scene As String, table As String)
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-fit-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Dim file = IO.Path.Combine(folder, "kinds.json")
        Dim second = If(scene = "polygon",
            "{""id"":""pentagon"",""type"":""polygon"",""vertices"":[[4.0,3.4],[3.6195,3.1236],[3.7648,2.6764],[4.2352,2.6764],[4.3805,3.1236]],""mass"":1.5,""friction"":0.35}",
            If(scene = "quadrilateral",
            "{""id"":""kite"",""type"":""polygon"",""vertices"":[[4.0,3.4],[3.6,3.0],[4.0,2.4],[4.4,3.0]],""fixed"":true,""friction"":0.35}",
            "{""id"":""crate"",""type"":""rectangle"",""x"":5,""y"":0,""width"":1.23456,""height"":0.987654,""fixed"":false,""mass"":2.5,""vx"":-1.5,""friction"":0.35}"))
        ' Two links of every kind for the Links table: a spring (its kind names k), a string to an anchor (its end names the point).
        Dim links = ",""links"":[{""id"":""spring1"",""type"":""spring"",""a"":""ball"",""b"":""peg"",""stiffness"":1234.5,""rest_length"":1.5}," &
                    "{""id"":""string2"",""type"":""string"",""a"":""ball"",""at"":[2.123456,4.654321],""length"":1.75}]"
        IO.File.WriteAllText(file, "{""format"":""physics-scene/1"",""world"":{""width"":8,""height"":5,""gravity"":9.81,""friction"":0.25,""static_friction"":0.4},""bodies"":[" &
            "{""id"":""slope"",""type"":""segment"",""x1"":0.2,""y1"":0.5,""x2"":3.123456,""y2"":1.5}," &
            second & "," &
            "{""id"":""table"",""type"":""rectangle"",""x"":6.5,""y"":0,""width"":1,""height"":0.5,""fixed"":true}," &
            "{""id"":""peg"",""type"":""circle"",""x"":6,""y"":3,""radius"":0.2,""fixed"":true}," &
            "{""id"":""ball"",""type"":""circle"",""x"":2,""y"":3,""radius"":0.25,""mass"":1,""vx"":-12.345678}]" & If(table = "Links", links, "") & "}")
        Try
            Dim args = If(scene = "", Array.Empty(Of String)(), {file})
            Using app As New AppDriver(New XSessionOptions With {.Screen = screen, .Dpi = dpi}, args)
                If scene <> "" Then app.WaitFor("^opened kinds.json: 5 bodies")
                Dim from = app.Mark()
                If large Then
                    app.Click("large-fonts")
                    app.WaitFor("^large fonts on$", skip:=from)
                    app.WaitFor("^ready$", skip:=from)
                    from = app.Mark()
                End If
                ' Another tab first: the window may open on this table, and choosing it again does nothing.
                Dim other = If(table = "Links", "Bodies", "Links")
                app.Click("tab-" & other.ToLowerInvariant())
                app.WaitFor("^tab " & other & "$", skip:=from)
                from = app.Mark()
                app.Click("tab-" & table.ToLowerInvariant())
                app.WaitFor("^tab " & table & "$", skip:=from)
                app.WaitFor("^row " & table & " 1: ", skip:=from)
                ' Let the values change as time runs (columns only grow): a row is traced again only when it changed.
                ' (The crate, the one moving rectangle, comes to rest on the floor at once.)
                from = app.Mark()
                If table <> "Rectangles" Then app.WaitFor("^row " & table & " \d+: ", skip:=from)
                from = app.Mark()
                app.Click("tab-" & other.ToLowerInvariant())
                app.WaitFor("^tab " & other & "$", skip:=from)
                from = app.Mark()
                app.Click("tab-" & table.ToLowerInvariant())
                app.WaitFor("^tab " & table & "$", skip:=from)
                Dim edge = app.LastMatch("^columns " & table & " right (\d+) visible (\d+)$")
                Dim right = Int(edge.Groups(1).Value), visible = Int(edge.Groups(2).Value)
                Assert.True(right <= visible, $"the {table} table's columns end at {right} px, past its visible {visible} px: the last columns need a sideways scroll" & vbLf & app.X.AppOutput())
                Dim widths As New Dictionary(Of Integer, (Width As Integer, Needs As Integer))
                For Each line In app.Lines()
                    Dim m = Regex.Match(line, "^column " & table & " (\d+) width (\d+) needs (\d+)$")
                    If m.Success Then widths(Int(m.Groups(1).Value)) = (Int(m.Groups(2).Value), Int(m.Groups(3).Value))
                Next
                Assert.Equal(If(table = "Circles", 10, If(table = "Links", 7, 12)), widths.Count)
                For Each kv In widths
                    Assert.True(kv.Value.Width >= kv.Value.Needs, $"column {kv.Key} of the {table} table is {kv.Value.Width} px wide; its header and values need {kv.Value.Needs} px")
                Next
                If scene = "polygon" Then app.LastMatch("^row Bodies \d+: pentagon \| #[0-9a-f]{6} \| pentagon \| ")
                If scene = "quadrilateral" Then app.LastMatch("^row Bodies \d+: kite \| fixed \| fixed quadrilateral \| ")
                app.X.Shoot(table.ToLowerInvariant() & "-table-" & screen.Replace("x24", "") & If(dpi > 0, "-" & dpi & "dpi", "") & If(large, "-large", "") & If(scene = "", "", "-" & scene))
            End Using
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub

    Private Shared Function Int(text As String) As Integer
        Return Integer.Parse(text, CultureInfo.InvariantCulture)
    End Function
End Class
