Option Strict On
Imports Xunit

''' <summary>
''' A test that drives the real window under Xvfb. In CI (CI=true) it always runs, so missing X tools
''' fail it loudly; elsewhere it is skipped, with the reason, when a tool is missing.
''' </summary>
<AttributeUsage(AttributeTargets.Method, AllowMultiple:=False)>
Public NotInheritable Class GuiFactAttribute
    Inherits FactAttribute

    Public Sub New()
        If Not XSession.IsCi Then
            Dim missing = XSession.MissingTools()
            If missing.Count > 0 Then Skip = "GUI test needs " & String.Join(", ", missing) & " (run: bash scripts/install-deps.sh test)"
        End If
    End Sub
End Class
