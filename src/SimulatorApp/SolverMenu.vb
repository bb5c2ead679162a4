Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>The solver menu: each solver with a line on what it is for, the one in use ticked; the choice is the presenter's.</summary>
Friend NotInheritable Class SolverMenu
    Implements IDisposable

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _button As Button
    Private ReadOnly _menu As New ContextMenuStrip()

    ''' <param name="button">the Solver button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        _kit = kit
        _button = button
        AddHandler _menu.Closed, Sub(s, e) _kit.Emit("solver menu closed")
    End Sub

    ''' <summary>Every caption the solver's button can have: it is made wide enough for the longest, so it never moves.</summary>
    Public Shared Function Captions() As IEnumerable(Of String)
        Return SolverChoice.Names.Select(AddressOf SolverChoice.ButtonCaption)
    End Function

    ''' <summary>Drops the menu down under its button, kept on the screen.</summary>
    Public Sub Show()
        Dim p = _kit.Presenter
        Dim theme = p.Theme
        _kit.Prepare(_menu, theme)
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        For Each solverName In SolverChoice.Names
            Dim chosen = solverName
            Dim item As New ToolStripMenuItem(SolverChoice.MenuLine(chosen)) With {.BackColor = back, .ForeColor = fore, .ToolTipText = SolverChoice.Purpose(chosen),
                .Checked = (p.SolverInUse = chosen)}
            AddHandler item.Click, Sub(s, e) _kit.Act(Sub() _kit.Presenter.ChooseSolver(chosen))
            _menu.Items.Add(item)
        Next
        _menu.Show(_kit.OnScreen(_button, _menu.GetPreferredSize(Size.Empty)))
        If _kit.Trace IsNot Nothing Then
            For i = 0 To _menu.Items.Count - 1
                Dim b = _menu.Items(i).Bounds
                Dim at = _menu.PointToScreen(b.Location)
                _kit.Emit("solver item " & i & " " & at.X & " " & at.Y & " " & b.Width & " " & b.Height & " " & SolverChoice.Names(i))
            Next
            _kit.TraceMenuBounds("solver menu", _menu)
            _kit.Emit("solver menu shown " & _menu.Items.Count)
        End If
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _menu.Dispose()
    End Sub
End Class
