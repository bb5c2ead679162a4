Option Strict On
Imports System.Text.RegularExpressions
Imports Xunit

''' <summary>Ctrl+Z and Ctrl+Y in the real window: a circle placed with the mouse is undone and redone, and a text box keeps Ctrl+Z for its own text.</summary>
<Collection(RealWindow.Name)>
Public Class UndoGuiTests
    <GuiFact>
    Public Sub CtrlZ_UndoesThePlacedCircle_CtrlY_PutsItBack_ATextBoxKeepsItsOwnUndo()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim id = app.PlaceCircle("0.3", "2", 4.0, 2.5)
            Dim from = app.Mark()
            ' The canvas has no keyboard focus of its own: the pause button keeps it after the click above.
            app.X.XDo("key", "ctrl+z")
            app.WaitFor("^key undo$", skip:=from)
            app.WaitFor("^undo the circle " & Regex.Escape(id) & " added$", skip:=from)
            Dim message = app.WaitFor("^message: (Undone: .*)$", skip:=from).Groups(1).Value
            Assert.Equal("Undone: the circle " & id & " added. Ctrl+Y does it again.", message)
            from = app.Mark()
            app.X.XDo("key", "ctrl+y")
            app.WaitFor("^redo the circle " & Regex.Escape(id) & " added$", skip:=from)
            ' The circle is back where it was placed: the pause lists it.
            app.ClickAndWait("pause", "^resumed$")
            from = app.Mark()
            app.Click("pause")
            app.WaitFor("^body " & Regex.Escape(id) & " at ", skip:=from)
            ' In a text box Ctrl+Z is the box's own: the scene is not undone.
            app.TypeInto("radius", "0.45")
            from = app.Mark()
            app.X.XDo("key", "ctrl+z")
            app.X.XDo("key", "ctrl+y")
            ' A frame later (the step key's trace proves the keys before it were handled), no undo came.
            app.Click("step")
            app.WaitFor("^step t=", skip:=from)
            Assert.DoesNotContain(app.Lines().Skip(from), Function(l) l.StartsWith("undo ", StringComparison.Ordinal) OrElse l = "key undo")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    ''' <summary>The solver menu in the real window: on the screen, each line whole, Verlet chosen with the mouse moves the scene, and the button says so.</summary>
    <GuiFact>
    Public Sub TheSolverMenu_ChoosesVerlet_AndTheButtonSaysSo()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x720x24"})
            Dim from = app.Mark()
            app.Click("solver")
            app.WaitFor("^solver menu shown 3$", skip:=from)
            Dim bounds = app.WaitFor("^solver menu at (-?\d+) (-?\d+) (\d+) (\d+) screen (\d+) (\d+) (fits|cut)$", skip:=from)
            Assert.Equal("fits", bounds.Groups(7).Value)
            Assert.True(CInt(bounds.Groups(1).Value) >= 0 AndAlso CInt(bounds.Groups(1).Value) + CInt(bounds.Groups(3).Value) <= CInt(bounds.Groups(5).Value), bounds.Value)
            Dim item = app.WaitFor("^solver item 1 (-?\d+) (-?\d+) (\d+) (\d+) verlet$", skip:=from)
            from = app.Mark()
            app.ClickAt(CInt(item.Groups(1).Value) + CInt(item.Groups(3).Value) \ 3, CInt(item.Groups(2).Value) + CInt(item.Groups(4).Value) \ 2)
            app.WaitFor("^solver verlet$", skip:=from)
            app.WaitFor("^message: Verlet \(fixed step\) from now: ", skip:=from)
            app.X.Shoot("solver-verlet")
            ' Time runs on with it: the pause lists the bodies, and the button's caption fits.
            from = app.Mark()
            app.Click("pause")
            app.WaitFor("^paused t=", skip:=from)
            Assert.EndsWith(" fits", app.Lines().Last(Function(l) l.StartsWith("control solver ", StringComparison.Ordinal)), StringComparison.Ordinal)
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
