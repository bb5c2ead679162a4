Option Strict On

#If NET Then
Imports System.Runtime.CompilerServices
#End If

''' <summary>
''' The grid's lanes copy each body's motion for the vectorised pair test (see UniformGrid). A copy
''' that lags its body would feed wrong predictions without any other sign, so tests can have every
''' lane checked after every event.
''' </summary>
Friend Module LaneCheck
    ''' <summary>Throws when a lane differs from its body or a gridded body is missing from its cell.</summary>
    Friend Sub Check(s As SolverState)
        Dim b = s.Bodies
        Dim grid = s.Grid
        For i = 0 To b.Count - 1
            Dim cell = b.Slot(i).Cell
            If cell < 0 Then Continue For
            Dim lane = grid.LaneOf(i)
            If lane < 0 Then
                Dim o = grid.OverflowHead(cell)
                While o >= 0 AndAlso o <> i
                    o = grid.OverflowNext(o)
                End While
                If o <> i Then Throw New InvalidOperationException($"body {i} is in neither a lane nor the overflow of cell {cell}")
                Continue For
            End If
            If lane \ UniformGrid.Lanes <> cell OrElse grid.LaneBody(lane) <> i OrElse
               lane - cell * UniformGrid.Lanes >= grid.Count(cell) Then
                Throw New InvalidOperationException($"body {i} has lane {lane}, which is not its own in cell {cell}")
            End If
#If NET Then
            If Not Unsafe.AddByteOffset(grid.Blocks(cell), grid.BlockShift).LaneIs(lane Mod UniformGrid.Lanes, b.Motion(i), b.Slot(i).ColTime) Then
                Throw New InvalidOperationException($"the lane of body {i} lags its motion at t = {s.Now} s")
            End If
#End If
        Next
    End Sub
End Module
