Option Strict On

' The grid's lanes hold a copy of each gridded body's motion and next collision time, which the
' vectorised pair test reads (see UniformGrid). The copy is published whenever the original changes:
' when a body's motion changes (Changed, with its counter), when it is synced or rescheduled, and
' when it moves to another lane. A lane that lags would feed wrong predictions, so tests can have
' every lane checked after every event.
Partial Public NotInheritable Class EventDrivenSolver
    ''' <summary>Checks every lane against its body after every event (slow: for tests).</summary>
    Friend Property CheckLanesEveryEvent As Boolean

    ''' <summary>Moves gridded body i to the cell at (col, row), if it is not there already, and publishes it there.</summary>
    Private Sub MoveToCell(i As Integer, col As Integer, row As Integer)
        Dim cell = row * _grid.Nx + col
        If cell = _ev(i).Cell Then Return
        Dim pulled = _grid.Remove(i, _ev(i).Cell)
        If pulled >= 0 Then Publish(pulled)
        _grid.Insert(i, cell)
        _ev(i).Cell = cell
        _ev(i).Col = col
        _ev(i).Row = row
        Publish(i)
    End Sub

    ''' <summary>
    ''' Body i's motion changed: events predicted with its old motion become stale (its counter), and
    ''' its lane shows the new motion at once, before anything is predicted against it.
    ''' </summary>
    Private Sub Changed(i As Integer)
        _ev(i).Count += 1
        Publish(i)
    End Sub

    ''' <summary>Copies body i's motion and next collision time into its grid lane (see UniformGrid).</summary>
    Private Sub Publish(i As Integer)
        _grid.Publish(i, _body(i), _ev(i).ColTime)
    End Sub

    ''' <summary>Gridded bodies that did not fit in their cell's lanes (for tests).</summary>
    Friend ReadOnly Property OverflowCount As Integer
        Get
            Dim count = 0
            For i = 0 To _n - 1
                If _ev(i).Cell >= 0 AndAlso _grid.LaneOf(i) < 0 Then count += 1
            Next
            Return count
        End Get
    End Property

    ''' <summary>Throws when a lane differs from its body or a gridded body is missing from its cell.</summary>
    Private Sub CheckLanes()
        For i = 0 To _n - 1
            Dim cell = _ev(i).Cell
            If cell < 0 Then Continue For
            Dim lane = _grid.LaneOf(i)
            If lane < 0 Then
                Dim o = _grid.OverflowHead(cell)
                While o >= 0 AndAlso o <> i
                    o = _grid.OverflowNext(o)
                End While
                If o <> i Then Throw New InvalidOperationException($"body {i} is in neither a lane nor the overflow of cell {cell}")
                Continue For
            End If
            If lane \ UniformGrid.Lanes <> cell OrElse _grid.LaneBody(lane) <> i OrElse
               lane - cell * UniformGrid.Lanes >= _grid.Count(cell) Then
                Throw New InvalidOperationException($"body {i} has lane {lane}, which is not its own in cell {cell}")
            End If
#If NET Then
            If Not _grid.Blocks(cell).LaneIs(lane Mod UniformGrid.Lanes, _body(i), _ev(i).ColTime) Then
                Throw New InvalidOperationException($"the lane of body {i} lags its motion at t = {_now} s")
            End If
#End If
        Next
    End Sub
End Class
