Option Strict On
Imports System.Globalization
Imports Xunit

''' <summary>The gas controls in the real window's Graphs tab: heat, cool, balls added and removed, each traced with the gas's temperature.</summary>
<Collection(RealWindow.Name)>
Public Class GasGuiTests
    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, CultureInfo.InvariantCulture)
    End Function

    <GuiFact>
    Public Sub HeatCoolAddAndRemove_FromTheGraphsTab()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x720x24"}, "--gas", "200")
            Dim from = app.Mark()
            app.Click("tab-graphs")
            app.WaitFor("^tab Graphs$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            app.ClickAndWait("graph-speeds", "^graph SpeedHistogram$")
            Dim heat = app.ClickAndWait("gas-heat", "^heat kT (\S+) to (\S+) J$")
            Assert.Equal(D(heat.Groups(1).Value) * 1.25, D(heat.Groups(2).Value), 5)
            Dim cool = app.ClickAndWait("gas-cool", "^cool kT (\S+) to (\S+) J$")
            Assert.Equal(D(cool.Groups(1).Value) / 1.25, D(cool.Groups(2).Value), 5)
            app.ClickAndWait("gas-add", "^added 10 balls, kT ")
            app.ClickAndWait("gas-remove", "^removed 10 balls$")
            ' The histogram counts every ball: 200 + 10 − 10.
            Dim shown = app.WaitFor("^graph: SpeedHistogram \|.* \| total 200 \|", timeout:=TimeSpan.FromSeconds(10), skip:=from)
            Assert.True(shown.Success)
            app.X.Shoot("gas-controls")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
