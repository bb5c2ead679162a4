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
End Class
