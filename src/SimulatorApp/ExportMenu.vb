Option Strict On
Imports System.Drawing
Imports System.Drawing.Imaging
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The Export menu: CSV of the tables, the collision log and the graph's series, and PNG pictures of
''' the graph (a slide's size) and the canvas (as large as it is on the screen), each through a Save
''' dialog. What is written, and what is said about it, is the presenter's (its ExportWriter).
''' </summary>
Friend NotInheritable Class ExportMenu
    Implements IDisposable

    ''' <summary>The exported graph picture's size at 96 dpi, px (twice as many on a 192-dpi screen).</summary>
    Public Shared ReadOnly GraphPictureSize As New Size(1280, 720)

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _button As Button
    Private ReadOnly _canvas As Control
    Private ReadOnly _painter As ScenePainter
    Private ReadOnly _menu As New ContextMenuStrip()

    ''' <param name="button">the Export button the menu drops down from</param>
    ''' <param name="canvas">the canvas, whose picture is exported as large as it is</param>
    ''' <param name="painter">paints the canvas's picture as the canvas paints itself</param>
    Public Sub New(kit As WindowKit, button As Button, canvas As Control, painter As ScenePainter)
        _kit = kit
        _button = button
        _canvas = canvas
        _painter = painter
        AddHandler _menu.Closed, Sub(s, e) _kit.Emit("export menu closed")
    End Sub

    ''' <summary>Drops the menu down under its button.</summary>
    Public Sub Show()
        Dim theme = _kit.Presenter.Theme
        _kit.Prepare(_menu, theme)
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        For i = 0 To SimulationPresenter.ExportNames.Count - 1
            Dim kind = CType(i, ExportKind)
            Dim item As New ToolStripMenuItem(SimulationPresenter.ExportNames(i)) With {.BackColor = back, .ForeColor = fore}
            ' After the menu has closed, so the dialog is not opened from inside the menu's click.
            AddHandler item.Click, Sub(s, e) _kit.Window.BeginInvoke(New Action(Sub() Export(kind)))
            _menu.Items.Add(item)
        Next
        _menu.Show(_kit.OnScreen(_button, _menu.GetPreferredSize(Size.Empty)))
        If _kit.Trace IsNot Nothing Then
            For i = 0 To _menu.Items.Count - 1
                Dim b = _menu.Items(i).Bounds
                Dim p = _menu.PointToScreen(b.Location)
                _kit.Emit("export item " & i & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & CType(i, ExportKind).ToString())
            Next
            _kit.Emit("export menu shown " & _menu.Items.Count)
        End If
    End Sub

    ''' <summary>Asks where to save an export and writes it there (the presenter says what happened).</summary>
    Private Sub Export(kind As ExportKind)
        Dim p = _kit.Presenter
        Dim png = kind = ExportKind.GraphPng OrElse kind = ExportKind.CanvasPng
        Dim title = "Export the " & SimulationPresenter.ExportNames(CInt(kind)).TrimEnd("…"c).ToLowerInvariant()
        Using d As New SaveFileDialog() With {
            .Title = title, .FileName = p.ExportFileName(kind), .AddExtension = True, .OverwritePrompt = True,
            .DefaultExt = If(png, "png", "csv"),
            .Filter = If(png, "PNG pictures (*.png)|*.png", "CSV files (*.csv)|*.csv") & "|All files (*.*)|*.*"}
            _kit.Emit("export dialog " & kind.ToString())
            If d.ShowDialog(_kit.Window) <> DialogResult.OK Then Return
            Select Case kind
                Case ExportKind.GraphPng
                    ' A slide's size (16:9), whatever room the tab has on screen: the picture is for a worksheet or a slide.
                    Dim w = _kit.S(GraphPictureSize.Width), h = _kit.S(GraphPictureSize.Height)
                    SavePicture(kind, d.FileName, w, h, Sub(g) GraphPainter.Paint(g, p.CurrentGraph(), p.Theme, _kit.Font, w, h, _kit.Dpi.Scale))
                Case ExportKind.CanvasPng
                    Dim w = Math.Max(1, _canvas.ClientSize.Width), h = Math.Max(1, _canvas.ClientSize.Height)
                    SavePicture(kind, d.FileName, w, h, Sub(g) _painter.Paint(g, p, w, h))
                Case Else
                    p.ExportCsv(kind, d.FileName)
            End Select
        End Using
        _canvas.Invalidate()
    End Sub

    Private Sub SavePicture(kind As ExportKind, path As String, width As Integer, height As Integer, draw As Action(Of Graphics))
        Using bmp As New Bitmap(width, height)
            bmp.SetResolution(CSng(_kit.Dpi.Graphics), CSng(_kit.Dpi.Graphics))
            Using g = Graphics.FromImage(bmp)
                draw(g)
            End Using
            _kit.Presenter.ExportPicture(kind, path, Sub(s) bmp.Save(s, ImageFormat.Png), width, height)
        End Using
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _menu.Dispose()
    End Sub
End Class
