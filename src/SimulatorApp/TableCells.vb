Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' Typing a value into a body table: a double click on a cell (or F2 on a row) opens an edit box
''' over the cell; Enter applies it, Esc or clicking elsewhere cancels. What may be typed, and what a
''' value does, is the presenter's (its TableEditor).
''' </summary>
Friend NotInheritable Class TableCells
    Implements IDisposable

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _host As Control
    Private ReadOnly _tables As List(Of BufferedListView)
    Private ReadOnly _cellBox As New TextBox() With {.Visible = False, .BorderStyle = BorderStyle.FixedSingle}
    Private _editTable As Integer = -1
    Private _editRow As Integer = -1
    Private _editColumn As Integer = -1
    Private _editOpening As String = ""
    ''' <summary>The quantity F2 opens: the one typed last (at first vx, the usual thing to set precisely).</summary>
    Private _lastQuantity As TableQuantity = TableQuantity.Vx

    ''' <param name="host">the window: the edit box is put on it, over the list (Mono paints a list view over any control inside it)</param>
    ''' <param name="tables">the body tables' lists, in tab order</param>
    Public Sub New(kit As WindowKit, host As Control, tables As List(Of BufferedListView))
        _kit = kit
        _host = host
        _tables = tables
        For Each list In _tables
            Dim table = _tables.IndexOf(list)
            AddHandler list.MouseDoubleClick, Sub(s, e) OnCellDoubleClick(table, e.X, e.Y)
            AddHandler list.KeyDown, Sub(s, e) OnTableKey(table, e)
        Next
        AddHandler _cellBox.KeyDown, AddressOf OnCellBoxKey
        ' Esc before the window sees it (it previews keys: Esc there drops a body being placed).
        AddHandler _cellBox.PreviewKeyDown, Sub(s, e) If e.KeyCode = Keys.Escape Then CloseCellBox(False)
        AddHandler _cellBox.Leave, Sub(s, e) CloseCellBox(False)
    End Sub

    ''' <summary>The row and column under (x, y) px of table <paramref name="table"/>'s list, or (−1, −1).</summary>
    Private Function CellAt(table As Integer, x As Integer, y As Integer) As (Row As Integer, Column As Integer)
        Dim list = _tables(table)
        If list.VirtualListSize = 0 Then Return (-1, -1)
        Dim first = list.GetItemRect(0)
        If first.Height <= 0 OrElse y < first.Top Then Return (-1, -1)
        Dim row = (y - first.Top) \ first.Height
        If row >= list.VirtualListSize Then Return (-1, -1)
        Dim left = first.Left
        For c = 0 To list.Columns.Count - 1
            Dim w = list.Columns(c).Width
            If x >= left AndAlso x < left + w Then Return (row, c)
            left += w
        Next
        Return (row, -1)
    End Function

    ''' <summary>The cell's rectangle in its list's coordinates, px.</summary>
    Private Function CellBounds(table As Integer, row As Integer, column As Integer) As Drawing.Rectangle
        Dim list = _tables(table)
        Dim first = list.GetItemRect(0)
        Dim left = first.Left
        For c = 0 To column - 1
            left += list.Columns(c).Width
        Next
        Return New Drawing.Rectangle(left, first.Top + row * first.Height, list.Columns(column).Width, first.Height)
    End Function

    Private Sub OnCellDoubleClick(table As Integer, x As Integer, y As Integer)
        Dim cell = CellAt(table, x, y)
        If cell.Row < 0 OrElse cell.Column < 0 Then Return
        OpenCellBox(table, cell.Row, cell.Column)
    End Sub

    Private Sub OnTableKey(table As Integer, e As KeyEventArgs)
        If e.KeyCode <> Keys.F2 Then Return
        Dim list = _tables(table)
        Dim row = If(list.SelectedIndices.Count > 0, list.SelectedIndices(0), If(list.FocusedItem IsNot Nothing, list.FocusedItem.Index, 0))
        Dim column = SimulationPresenter.ColumnOf(table, _lastQuantity)
        If column < 0 Then column = SimulationPresenter.ColumnOf(table, TableQuantity.Vx)
        OpenCellBox(table, row, column)
        e.Handled = True
    End Sub

    ''' <summary>Opens the edit box over a cell the teacher may type into; says why not otherwise.</summary>
    Private Sub OpenCellBox(table As Integer, row As Integer, column As Integer)
        CloseCellBox(False)
        If Not _kit.Presenter.CanEditCell(table, row, column) Then
            ' The presenter gives the reason (a fixed body, a column that is worked out from others).
            _kit.Act(Sub() _kit.Presenter.EditCell(table, row, column, Nothing))
            _kit.Emit("edit refused " & SimulationPresenter.Tables(table).Title & " " & row & " " & column)
            Return
        End If
        _editTable = table
        _editRow = row
        _editColumn = column
        _editOpening = _kit.Presenter.CellEditText(table, row, column)
        Dim list = _tables(table)
        ' On the form, over the list: Mono paints a list view over any control placed inside it.
        If _cellBox.Parent IsNot _host Then _host.Controls.Add(_cellBox)
        Dim r = CellBounds(table, row, column)
        Dim at = _host.PointToClient(list.PointToScreen(r.Location))
        _cellBox.Font = list.Font
        _cellBox.BackColor = ScenePainter.Rgb(_kit.Presenter.Theme.Field)
        _cellBox.ForeColor = ScenePainter.Rgb(_kit.Presenter.Theme.PanelText)
        _cellBox.SetBounds(at.X, at.Y, Math.Max(r.Width, _kit.S(70)), Math.Max(r.Height, _cellBox.PreferredHeight))
        _cellBox.Text = _editOpening
        _cellBox.Visible = True
        _cellBox.BringToFront()
        _cellBox.Focus()
        _cellBox.SelectAll()
        Dim p = list.PointToScreen(r.Location)
        _kit.Emit("edit open " & SimulationPresenter.Tables(table).Title & " " & row & " " & list.Columns(column).Text & " [" & _editOpening & "] at " & p.X & " " & p.Y)
    End Sub

    Private Sub OnCellBoxKey(sender As Object, e As KeyEventArgs)
        If e.KeyCode = Keys.Enter OrElse e.KeyCode = Keys.Return Then
            CloseCellBox(True)
            e.Handled = True
            e.SuppressKeyPress = True
        ElseIf e.KeyCode = Keys.Escape Then
            CloseCellBox(False)
            e.Handled = True
            e.SuppressKeyPress = True
        End If
    End Sub

    ''' <summary>Closes the edit box; with <paramref name="apply"/>, hands what was typed to the presenter (unless it is what the box opened with).</summary>
    Private Sub CloseCellBox(apply As Boolean)
        If _editTable < 0 Then Return
        Dim table = _editTable, row = _editRow, column = _editColumn
        Dim text = _cellBox.Text
        _editTable = -1
        _cellBox.Visible = False
        Dim list = _tables(table)
        If apply AndAlso text.Trim() <> _editOpening Then
            _lastQuantity = SimulationPresenter.EditableQuantity(table, column)
            _kit.Act(Sub() _kit.Presenter.EditCell(table, row, column, text))
            _kit.Emit("edit applied [" & text & "]")
        Else
            _kit.Emit("edit cancelled")
        End If
        If list.CanFocus Then list.Focus()
    End Sub

    ''' <summary>Whether the edit box is open (it keeps Enter for itself).</summary>
    Public ReadOnly Property IsOpen As Boolean
        Get
            Return _cellBox.Visible
        End Get
    End Property

    ''' <summary>With --trace: where the editable cells of the first rows of table <paramref name="table"/> (the one on show) are (GUI tests double-click them there).</summary>
    Public Sub TraceCells(table As Integer)
        If _kit.Trace Is Nothing Then Return
        If table < 0 OrElse table >= _tables.Count Then Return
        Dim list = _tables(table)
        If Not list.IsHandleCreated OrElse list.VirtualListSize = 0 Then Return
        Dim name = SimulationPresenter.Tables(table).Title.ToLowerInvariant()
        For index = 0 To Math.Min(3, list.VirtualListSize) - 1
            For c = 0 To list.Columns.Count - 1
                Dim q = SimulationPresenter.EditableQuantity(table, c)
                If q = TableQuantity.None Then Continue For
                Dim r = CellBounds(table, index, c)
                Dim p = list.PointToScreen(r.Location)
                _kit.Emit("control cell-" & name & "-" & index & "-" & q.ToString().ToLowerInvariant() & " " & p.X & " " & p.Y & " " & r.Width & " " & r.Height & " fits")
            Next
        Next
    End Sub

    ''' <summary>Its controls (the window disposes them too, with the panel; a second time does nothing).</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        _cellBox.Dispose()
    End Sub
End Class
