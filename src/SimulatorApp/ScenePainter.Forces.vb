Option Strict On
Imports System.Drawing
Imports PhysicsEngine.Presentation

' The free-body diagram of the chosen body on the canvas: an arrow per force from its centre of mass, in a
' colour per kind (their labels are placed with the others', see CanvasLabelLayout).
Partial Friend NotInheritable Class ScenePainter
    ''' <summary>The colour of a force's arrow: apart from the velocity arrows' and from one another (lighter on the dark theme).</summary>
    Private Shared Function ForceColour(kind As ForceKind, theme As Theme) As Integer
        Dim dark = theme.IsHighContrast
        Select Case kind
            Case ForceKind.Weight : Return If(dark, &HEA80FC, &H6A1B9A)
            Case ForceKind.Normal : Return If(dark, &H82B1FF, &H1565C0)
            Case ForceKind.Friction : Return If(dark, &HFF8A80, &HC62828)
            Case ForceKind.Tension, ForceKind.Spring : Return If(dark, &HB9F6CA, &H2E7D32)
            Case Else : Return If(dark, &HFFD180, &HE65100)
        End Select
    End Function

    ''' <summary>Each force on the chosen body while Forces is on, as an arrow from its centre of mass.</summary>
    Private Sub DrawForces(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        For Each a In p.ForceArrows()
            Dim s = view.ToScreen(a.Start), t = view.ToScreen(a.Tip)
            Arrow(g, PenOf(ForceColour(a.Kind, theme), 3 * k), CSng(s.X), CSng(s.Y), CSng(t.X), CSng(t.Y), k)
        Next
    End Sub
End Class
