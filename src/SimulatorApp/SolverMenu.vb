Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>The solver menu: each solver with a line on what it is for, the one in use ticked; the choice is the presenter's.</summary>
Friend NotInheritable Class SolverMenu
    Inherits DropDownMenu

    ''' <param name="button">the Solver button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        MyBase.New(kit, button, "solver")
    End Sub

    ''' <summary>Every caption the solver's button can have: it is made wide enough for the longest, so it never moves.</summary>
    Public Shared Function Captions() As IEnumerable(Of String)
        Return SolverChoice.Names.Select(AddressOf SolverChoice.ButtonCaption)
    End Function

    ''' <summary>Drops the menu down under its button, kept on the screen.</summary>
    Public Sub Show()
        Begin()
        Dim p = Kit.Presenter
        For Each solverName In SolverChoice.Names
            Dim chosen = solverName
            Strip.Items.Add(NewItem(SolverChoice.MenuLine(chosen), SolverChoice.Purpose(chosen), Sub() Kit.Presenter.ChooseSolver(chosen), p.SolverInUse = chosen))
        Next
        Drop(SolverChoice.Names)
    End Sub
End Class
