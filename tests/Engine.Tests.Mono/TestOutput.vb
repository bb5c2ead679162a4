Option Strict On
Imports System.Text
Imports Xunit.Abstractions

Namespace Mono
    ''' <summary>What a test writes with ITestOutputHelper: kept, and shown only when the test fails.</summary>
    Friend NotInheritable Class TestOutput
        Implements ITestOutputHelper

        Private ReadOnly _text As New StringBuilder()

        ''' <summary>Everything written so far.</summary>
        Public Overrides Function ToString() As String
            Return _text.ToString()
        End Function

        Public Sub WriteLine(message As String) Implements ITestOutputHelper.WriteLine
            _text.AppendLine(message)
        End Sub

        Public Sub WriteLine(format As String, ParamArray args() As Object) Implements ITestOutputHelper.WriteLine
            _text.AppendLine(String.Format(Globalization.CultureInfo.InvariantCulture, format, args))
        End Sub
    End Class
End Namespace
