Option Strict On
Imports Xunit

''' <summary>A <see cref="GuiFactAttribute"/> with cases: runs in CI always, elsewhere skipped with the reason when an X tool is missing.</summary>
<AttributeUsage(AttributeTargets.Method, AllowMultiple:=False)>
Public NotInheritable Class GuiTheoryAttribute
    Inherits TheoryAttribute

    Public Sub New()
        If Not XSession.IsCi Then
            Dim missing = XSession.MissingTools()
            If missing.Count > 0 Then Skip = "GUI test needs " & String.Join(", ", missing) & " (run: bash scripts/install-deps.sh test)"
        End If
    End Sub
End Class
