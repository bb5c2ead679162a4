Option Strict On
Imports System.Windows.Forms

''' <summary>Entry point of the classroom simulator.</summary>
Public NotInheritable Class Program
    Private Sub New()
    End Sub

    <STAThread>
    Public Shared Sub Main()
        Application.EnableVisualStyles()
        Application.SetCompatibleTextRenderingDefault(False)
        AddHandler Application.ThreadException, Sub(s, e) ShowError(e.Exception)
        Using form As New MainForm(New PhysicsEngine.Presentation.SimulationPresenter())
            Application.Run(form)
        End Using
    End Sub

    ''' <summary>The last line of defence: a message, never a crash.</summary>
    Private Shared Sub ShowError(ex As Exception)
        Console.Error.WriteLine(ex.ToString())
        MessageBox.Show(ex.Message, "Collision Simulator", MessageBoxButtons.OK, MessageBoxIcon.Warning)
    End Sub
End Class
