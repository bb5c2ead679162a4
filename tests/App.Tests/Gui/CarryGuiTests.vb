Option Strict On
Imports System.Globalization
Imports Xunit

''' <summary>Carrying a body on a string in the real window: the hand keeps to the string, and the run goes on after it lets go.</summary>
<Collection(RealWindow.Name)>
Public Class CarryGuiTests
    ''' <summary>
    ''' A triangle hangs on a 1.5 m string. Carried far past the string's reach with the right button and let go,
    ''' it used to leave the string longer than itself: the solver could not get past that state, the window
    ''' ignored every key for about a minute, and every later Resume froze again. Now the hand stops at the
    ''' string's length, and after letting go the window answers Pause at once, twice over, with time running
    ''' on and the string never longer than itself.
    ''' </summary>
    <GuiFact>
    Public Sub CarryingAPolygonPastItsStringsLength_AndLettingGo_LeavesTheWindowAnswering()
        Const anchorX As Double = 5.15, anchorY As Double = 4.5, length As Double = 1.5
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-carry-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Try
            Dim scene = IO.Path.Combine(folder, "hanging-triangle.json")
            IO.File.WriteAllText(scene, String.Format(CultureInfo.InvariantCulture,
                "{{""format"": ""physics-scene/1"", ""world"": {{""width"": 10, ""height"": 10, ""gravity"": 9.81, ""restitution"": 0.5, ""walls"": true}}, " &
                """bodies"": [{{""id"": ""p"", ""type"": ""polygon"", ""vertices"": [[5, 3], [5.3, 3], [5.15, 3.3]], ""mass"": 1}}], " &
                """links"": [{{""id"": ""s"", ""type"": ""string"", ""a"": ""p"", ""at"": [{0:R}, {1:R}], ""length"": {2:R}}}]}}", anchorX, anchorY, length))
            Using app As New AppDriver(New XSessionOptions(), scene)
                app.WaitFor("^opened hanging-triangle.json: 1 bodies$")
                Dim from = app.Mark()
                app.ClickAndWait("pause", "^paused t=")
                Dim at = app.WaitFor("^body p at \((\S+), (\S+)\) m", skip:=from)
                Dim body = app.Screen(AppDriver.Dbl(at.Groups(1).Value), AppDriver.Dbl(at.Groups(2).Value))
                ' Carried while paused, down and to the right, far past where the string reaches.
                Dim far = app.Screen(8.5, 0.8)
                app.Drag(3, body.X, body.Y, far.X, far.Y, 12)
                ' One step from there moves time on.
                Dim t0 = AppDriver.Dbl(app.LastMatch("^paused t=(\S+) s").Groups(1).Value)
                from = app.Mark()
                app.Click("step")
                Dim stepped = app.WaitFor("^step t=(\S+)", skip:=from)
                Assert.True(AppDriver.Dbl(stepped.Groups(1).Value) > t0, $"a step from t = {t0} s went nowhere: {stepped.Value}")
                Dim state = app.WaitFor("^state p (\S+) (\S+) ", skip:=from)
                Dim carried = Math.Sqrt((AppDriver.Dbl(state.Groups(1).Value) - anchorX) ^ 2 + (AppDriver.Dbl(state.Groups(2).Value) - anchorY) ^ 2)
                Assert.True(carried <= length * (1 + 0.000000001), $"carried and let go, the triangle is {carried} m from the anchor, on a {length} m string")
                For round = 1 To 2
                    app.ClickAndWait("pause", "^resumed$")
                    ' Let it run a moment (the run is not waited on: it must answer whatever it is doing).
                    Threading.Thread.Sleep(400)
                    from = app.Mark()
                    Dim clock = Diagnostics.Stopwatch.StartNew()
                    app.ClickAndWait("pause", "^paused t=")
                    Dim answered = clock.Elapsed.TotalSeconds
                    Dim paused = app.WaitFor("^paused t=(\S+) s", skip:=from)
                    Dim p = app.WaitFor("^body p at \((\S+), (\S+)\) m", skip:=from)
                    Dim x = AppDriver.Dbl(p.Groups(1).Value), y = AppDriver.Dbl(p.Groups(2).Value)
                    Dim reach = Math.Sqrt((x - anchorX) ^ 2 + (y - anchorY) ^ 2)
                    Assert.True(answered < 2, $"round {round}: Pause took {answered:0.00} s to answer")
                    Assert.True(AppDriver.Dbl(paused.Groups(1).Value) >= AppDriver.Dbl(stepped.Groups(1).Value), "time went back")
                    ' The string, at most taut, keeps the triangle within its length of the anchor (the trace has 3 decimals).
                    Assert.True(reach <= length + 0.002, $"round {round}: the triangle is {reach:0.000} m from the anchor, on a {length} m string")
                Next
                app.X.Shoot("carried-triangle")
                Assert.True(app.X.AppIsRunning)
            End Using
        Finally
            Try
                IO.Directory.Delete(folder, True)
            Catch ex As IO.IOException
            End Try
        End Try
    End Sub
End Class
