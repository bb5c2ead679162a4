Option Strict On
Imports System.Globalization
Imports Xunit

''' <summary>The measuring tools in the real window: the tape laid under a pendulum's pivot, and the stopwatch timing the bob's passes through it.</summary>
<Collection(RealWindow.Name)>
Public Class MeasuringGuiTests
    ''' <summary>
    ''' A 1.5 m pendulum released from θ0 = 0.1 rad: its period is 2π√(L/g) = 2.4572 s, longer by
    ''' θ0²/16 = 6 parts in 10⁴ at this amplitude. The tape is dragged down from the pivot, the bob's
    ''' passes through the tape's line are timed, and the period read from the trace.
    ''' </summary>
    <GuiFact>
    Public Sub TheStopwatch_TimesAPendulumsPasses_ItsPeriodIs2PiRootLOverG()
        Const length As Double = 1.5, theta0 As Double = 0.1, g As Double = 9.81
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-measure-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Try
            Dim bobX = 2.0 + length * Math.Sin(theta0), bobY = 3.5 - length * Math.Cos(theta0)
            Dim scene = IO.Path.Combine(folder, "small-swing.json")
            IO.File.WriteAllText(scene, String.Format(CultureInfo.InvariantCulture,
                "{{""format"": ""physics-scene/1"", ""world"": {{""width"": 4, ""height"": 4, ""gravity"": {3}, ""restitution"": 1.0, ""walls"": true}}, " &
                """bodies"": [{{""id"": ""bob"", ""type"": ""circle"", ""x"": {0:R}, ""y"": {1:R}, ""radius"": 0.1, ""mass"": 1.0}}], " &
                """links"": [{{""id"": ""rod"", ""type"": ""rod"", ""a"": ""bob"", ""at"": [2.0, 3.5], ""length"": {2:R}}}]}}", bobX, bobY, length, g))
            Using app As New AppDriver(New XSessionOptions(), scene)
                app.WaitFor("^opened small-swing.json: 1 bodies$")
                app.ClickAndWait("pause", "^paused t=")
                ' The tape, from the pivot straight down past the bob's lowest point.
                ChooseFromMenu(app, "tape")
                app.WaitFor("^tape on$")
                Dim pivot = app.Screen(2.0, 3.5), below = app.Screen(2.0, 1.7)
                Dim from = app.Mark()
                app.Drag(1, pivot.X, pivot.Y, below.X, below.Y)
                Dim tape = app.WaitFor("^tape (\S+) m at (\S+) deg from ", skip:=from)
                Assert.Equal(1.8, AppDriver.Dbl(tape.Groups(1).Value), 1)
                Assert.Equal(90.0, AppDriver.Dbl(tape.Groups(2).Value), 6)
                ' The bob's passes through the tape's line, and the stopwatch running.
                ChooseFromMenu(app, "passes")
                app.WaitFor("^pass line choosing$")
                ' Where the pause found the bob.
                Dim at = app.LastMatch("^body bob at \((\S+), (\S+)\) m")
                Dim bob = app.Screen(AppDriver.Dbl(at.Groups(1).Value), AppDriver.Dbl(at.Groups(2).Value))
                from = app.Mark()
                app.ClickAt(bob.X, bob.Y)
                app.WaitFor("^pass line bob through ", skip:=from)
                ChooseFromMenu(app, "start-stop")
                app.WaitFor("^stopwatch started at t=")
                from = app.Mark()
                app.ClickAndWait("pause", "^resumed$")
                Dim third = app.WaitFor("^pass bob 3 t=(\S+) s period (\S+) s$", TimeSpan.FromSeconds(60), from)
                app.ClickAndWait("pause", "^paused t=")
                Dim period = AppDriver.Dbl(third.Groups(2).Value)
                Dim small = 2 * Math.PI * Math.Sqrt(length / g)
                ' Within 1 part in 10³ of 2π√(L/g) (the amplitude adds 6 parts in 10⁴), and within 2 parts in 10⁵ of the period for this amplitude.
                Assert.True(Math.Abs(period / small - 1) < 0.001, $"period {period} s against 2π√(L/g) = {small} s")
                Dim expected = small * (1 + theta0 * theta0 / 16 + 11 * theta0 ^ 4 / 3072)
                Assert.True(Math.Abs(period / expected - 1) < 0.00002, $"period {period} s against {expected} s for θ0 = {theta0} rad")
                ' A frame later the readout is on the canvas: look at the screenshot.
                from = app.Mark()
                app.Click("step")
                app.WaitFor("^step t=", skip:=from)
                app.X.Shoot("stopwatch-pendulum")
                Assert.True(app.X.AppIsRunning)
            End Using
        Finally
            Try
                IO.Directory.Delete(folder, True)
            Catch ex As IO.IOException
            End Try
        End Try
    End Sub

    ''' <summary>The protractor in the real window: over each ramp of the inclined plane, its angle (20° and 35°) at its lower end.</summary>
    <GuiFact>
    Public Sub TheProtractor_OverEachRamp_ReadsItsAngle()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "inclined-plane.json"))
            app.WaitFor("^opened inclined-plane.json: 4 bodies$")
            app.ClickAndWait("pause", "^paused t=")
            ' Three quarters up the gentle ramp (0.5, 0.25) to (4.73, 1.79), clear of its block.
            Dim gentle = app.Screen(0.5 + 0.75 * 4.2286, 0.25 + 0.75 * 1.5391)
            Dim from = app.Mark()
            app.MoveTo(gentle.X - 20, gentle.Y - 40)
            app.MoveTo(gentle.X, gentle.Y)
            Dim reading = app.WaitFor("^protractor (\S+) deg from \((\S+), (\S+)\)$", skip:=from)
            Assert.Equal(20.0, AppDriver.Dbl(reading.Groups(1).Value), 2)
            Assert.Equal(0.5, AppDriver.Dbl(reading.Groups(2).Value), 3)
            ' A quarter up the steep ramp, which rises to the left from (9.5, 0.25).
            Dim steep = app.Screen(9.5 - 0.25 * 3.6862, 0.25 + 0.25 * 2.5811)
            from = app.Mark()
            app.MoveTo(steep.X + 20, steep.Y - 40)
            app.WaitFor("^protractor none$", skip:=from)
            app.MoveTo(steep.X, steep.Y)
            reading = app.WaitFor("^protractor (\S+) deg from \((\S+), (\S+)\)$", skip:=from)
            Assert.Equal(35.0, AppDriver.Dbl(reading.Groups(1).Value), 2)
            Assert.Equal(9.5, AppDriver.Dbl(reading.Groups(2).Value), 3)
            ' A frame later the arc is painted.
            from = app.Mark()
            app.Click("step")
            app.WaitFor("^step t=", skip:=from)
            app.X.Shoot("protractor-steep-ramp")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    ''' <summary>Drops the Measure menu down and clicks the item named <paramref name="name"/>.</summary>
    Private Shared Sub ChooseFromMenu(app As AppDriver, name As String)
        Dim from = app.Mark()
        app.Click("measure")
        app.WaitFor("^measure menu shown 5$", skip:=from)
        Dim item = app.WaitFor("^measure item \d+ (-?\d+) (-?\d+) (\d+) (\d+) " & name & "$", skip:=from)
        app.ClickAt(CInt(item.Groups(1).Value) + CInt(item.Groups(3).Value) \ 3, CInt(item.Groups(2).Value) + CInt(item.Groups(4).Value) \ 2)
    End Sub
End Class
