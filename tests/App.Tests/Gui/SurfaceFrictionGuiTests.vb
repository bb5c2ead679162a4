Option Strict On
Imports System.Threading
Imports Xunit

''' <summary>A surface's own μ typed into the Bodies table in the real window: the inclined-plane lesson's steep ramp.</summary>
<Collection(RealWindow.Name)>
Public Class SurfaceFrictionGuiTests
    <GuiFact>
    Public Sub TypingARampsMuIntoTheBodiesTable_SetsIt_AndTheRowShowsIt()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "inclined-plane.json"))
            app.WaitFor("^opened inclined-plane.json: 4 bodies$")
            app.ClickAndWait("pause", "^paused t=")
            Dim from = app.Mark()
            app.Click("tab-bodies")
            app.WaitFor("^tab Bodies$", skip:=from)
            ' Row 1 of the Bodies table is the steep ramp; its μk is the world's until it has its own.
            app.WaitFor("^row Bodies 1: steep \| .* \| 0\.4 \(world\) \| 0\.5 \(world\)$", skip:=from)
            Dim m = app.WaitFor("^control cell-bodies-1-kineticfriction (-?\d+) (-?\d+) (\d+) (\d+) fits$", skip:=from)
            Dim x = Integer.Parse(m.Groups(1).Value, Globalization.CultureInfo.InvariantCulture) + Integer.Parse(m.Groups(3).Value, Globalization.CultureInfo.InvariantCulture) \ 2
            Dim y = Integer.Parse(m.Groups(2).Value, Globalization.CultureInfo.InvariantCulture) + Integer.Parse(m.Groups(4).Value, Globalization.CultureInfo.InvariantCulture) \ 2
            from = app.Mark()
            app.MoveTo(x, y)
            app.X.XDo("click", "--repeat", "2", "--delay", "80", "1")
            app.WaitFor("^edit open Bodies 1 μk \[\]", skip:=from)
            app.TypeAndEnter("1,2")
            app.WaitFor("^edited steep μk = 1\.2$", skip:=from)
            app.WaitFor("^row Bodies 1: steep \| .* \| 1\.2 \| 1\.2 \(= μk\)$", skip:=from)
            Thread.Sleep(300)
            app.X.Shoot("surface-mu")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
