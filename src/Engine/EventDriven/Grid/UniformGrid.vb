Option Strict On

#If NET Then
Imports System.Runtime.CompilerServices
Imports System.Runtime.InteropServices
#End If

''' <summary>
''' A uniform grid over the container for the event-driven solver. Each cell is at least as wide as
''' the largest gridded circle's diameter, so two gridded circles can touch only when their cells are
''' neighbours (3 × 3). The static obstacles (fixed circles, rectangles) are listed in every cell
''' they can be touched from. The outermost cells extend to infinity, so a circle outside the
''' container still has a cell.
''' <para>
''' Movable circles sit in <see cref="Lanes"/> lanes per cell. Each lane keeps a copy of its body's
''' motion and next collision time (published by the solver whenever they change), laid out field
''' by field, so the solver tests a whole cell's bodies with one vector operation per field and the
''' cells of a row lie side by side in memory. A cell holding more than <see cref="Lanes"/> bodies
''' keeps the rest in a linked overflow list, tested one by one.
''' </para>
''' Fields are Friend so the solver's hot loop reads them directly.
''' </summary>
Friend NotInheritable Class UniformGrid
    ''' <summary>Bodies per cell held in lanes (one 256-bit vector of doubles).</summary>
    Friend Const Lanes As Integer = 4

    Friend Nx As Integer
    Friend Ny As Integer
    ''' <summary>Cell width and height, m.</summary>
    Friend CellWidth As Double
    Friend CellHeight As Double
    ''' <summary>Bodies in each cell's lanes (0 … <see cref="Lanes"/>).</summary>
    Friend Count As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Body in lane k of cell c: LaneBody(c · Lanes + k).</summary>
    Friend LaneBody As Integer() = Array.Empty(Of Integer)()
#If NET Then
    ''' <summary>
    ''' Published motion of each cell's lanes (only where the vectorised pair test exists): cell c's
    ''' block starts <see cref="BlockShift"/> bytes into Blocks(c), read and written through
    ''' Unsafe.AddByteOffset(Blocks(c), BlockShift). The array is pinned and one block longer, and the
    ''' shift puts every block on a 64-byte cache-line boundary: a block then spans exactly four lines
    ''' (not five) and no 32-byte field load straddles two lines, which a heap array's 8-byte
    ''' alignment gives only by chance.
    ''' </summary>
    Friend Blocks As LaneBlock() = Array.Empty(Of LaneBlock)()
    ''' <summary>Bytes from the start of Blocks(c) to cell c's block (0 … 56).</summary>
    Friend BlockShift As IntPtr
#End If
    ''' <summary>Lane of each body (c · Lanes + k), or −1 when it is in an overflow list or not gridded.</summary>
    Friend LaneOf As Integer() = Array.Empty(Of Integer)()
    ''' <summary>First body in each cell's overflow list, −1 when none.</summary>
    Friend OverflowHead As Integer() = Array.Empty(Of Integer)()
    Friend OverflowNext As Integer() = Array.Empty(Of Integer)()
    Friend OverflowPrev As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Static obstacles of cell c are StaticItems(StaticStart(c)) … StaticItems(StaticStart(c + 1) − 1).</summary>
    Friend StaticStart As Integer() = Array.Empty(Of Integer)()
    Friend StaticItems As Integer() = Array.Empty(Of Integer)()

    ''' <summary>Lays out cells of at least <paramref name="minCell"/> metres over width × height, all empty.</summary>
    Friend Sub Layout(width As Double, height As Double, minCell As Double, bodyCount As Integer, maxCells As Integer)
        Nx = CInt(Math.Max(1, Math.Min(4096, Math.Floor(width / minCell))))
        Ny = CInt(Math.Max(1, Math.Min(4096, Math.Floor(height / minCell))))
        While CLng(Nx) * Ny > maxCells AndAlso (Nx > 1 OrElse Ny > 1)
            If Nx >= Ny Then Nx = Math.Max(1, Nx \ 2) Else Ny = Math.Max(1, Ny \ 2)
        End While
        CellWidth = width / Nx
        CellHeight = height / Ny
        Dim cells = Nx * Ny
        If Count.Length < cells Then
            Count = New Integer(cells - 1) {}
            OverflowHead = New Integer(cells - 1) {}
            LaneBody = New Integer(cells * Lanes - 1) {}
#If NET Then
            Blocks = GC.AllocateArray(Of LaneBlock)(cells + 1, pinned:=True)
            Dim address = Marshal.UnsafeAddrOfPinnedArrayElement(Blocks, 0).ToInt64()
            BlockShift = New IntPtr((64 - address Mod 64) Mod 64)
#End If
        End If
        Array.Clear(Count, 0, cells)
        For c = 0 To cells - 1
            OverflowHead(c) = -1
        Next
        If LaneOf.Length < bodyCount Then
            LaneOf = New Integer(bodyCount - 1) {}
            OverflowNext = New Integer(bodyCount - 1) {}
            OverflowPrev = New Integer(bodyCount - 1) {}
        End If
        For i = 0 To bodyCount - 1
            LaneOf(i) = -1
        Next
    End Sub

    Friend Function ColumnOf(x As Double) As Integer
        Dim c = Math.Floor(x / CellWidth)
        If Not (c >= 0) Then Return 0 ' also NaN
        If c >= Nx Then Return Nx - 1
        Return CInt(c)
    End Function

    Friend Function RowOf(y As Double) As Integer
        Dim r = Math.Floor(y / CellHeight)
        If Not (r >= 0) Then Return 0
        If r >= Ny Then Return Ny - 1
        Return CInt(r)
    End Function

    ''' <summary>Puts body i in a free lane of the cell, or in its overflow list. The caller publishes it.</summary>
    Friend Sub Insert(i As Integer, cell As Integer)
        Dim k = Count(cell)
        If k < Lanes Then
            Dim lane = cell * Lanes + k
            LaneBody(lane) = i
            LaneOf(i) = lane
            Count(cell) = k + 1
            Return
        End If
        Dim h = OverflowHead(cell)
        OverflowNext(i) = h
        OverflowPrev(i) = -1
        If h >= 0 Then OverflowPrev(h) = i
        OverflowHead(cell) = i
        LaneOf(i) = -1
    End Sub

    ''' <summary>
    ''' Takes body i out of the cell. The cell's last lane moves into the gap (with its data); if the
    ''' cell had an overflow, one of those bodies takes the freed lane and is returned, for the caller
    ''' to publish. Otherwise −1.
    ''' </summary>
    Friend Function Remove(i As Integer, cell As Integer) As Integer
        Dim lane = LaneOf(i)
        If lane < 0 Then
            Unlink(i, cell)
            Return -1
        End If
        Dim last = cell * Lanes + Count(cell) - 1
        If lane <> last Then
            Dim moved = LaneBody(last)
            LaneBody(lane) = moved
            LaneOf(moved) = lane
#If NET Then
            Unsafe.AddByteOffset(Blocks(cell), BlockShift).CopyLane(last - cell * Lanes, lane - cell * Lanes)
#End If
        End If
        Count(cell) -= 1
        LaneOf(i) = -1
        Dim h = OverflowHead(cell)
        If h < 0 Then Return -1
        Unlink(h, cell)
        Insert(h, cell)
        Return h
    End Function

    Private Sub Unlink(i As Integer, cell As Integer)
        Dim p = OverflowPrev(i), n = OverflowNext(i)
        If p >= 0 Then OverflowNext(p) = n Else OverflowHead(cell) = n
        If n >= 0 Then OverflowPrev(n) = p
    End Sub

    ''' <summary>Copies body i's motion (and next collision time, s) into its lane; nothing when it has none.</summary>
    Friend Sub Publish(i As Integer, ByRef state As Motion, colTime As Double)
        Dim lane = LaneOf(i)
        If lane < 0 Then Return
#If NET Then
        Unsafe.AddByteOffset(Blocks(lane \ Lanes), BlockShift).SetLane(lane Mod Lanes, state, colTime)
#End If
    End Sub

    ''' <summary>Copies body i's next collision time (s) into its lane; nothing when it has none.</summary>
    Friend Sub PublishColTime(i As Integer, colTime As Double)
        Dim lane = LaneOf(i)
        If lane < 0 Then Return
#If NET Then
        Unsafe.AddByteOffset(Blocks(lane \ Lanes), BlockShift).SetColTime(lane Mod Lanes, colTime)
#End If
    End Sub

    ''' <summary>
    ''' Lists static obstacle k (bounding box xmin … ymax, m) in every cell from which a gridded circle
    ''' (radius ≤ half a cell) could touch it. Call with all boxes at once.
    ''' </summary>
    Friend Sub SetStatics(xmin As Double(), ymin As Double(), xmax As Double(), ymax As Double(), count As Integer)
        Dim cells = Nx * Ny
        If StaticStart.Length < cells + 1 Then StaticStart = New Integer(cells) {}
        Array.Clear(StaticStart, 0, cells + 1)
        Dim mx = 0.5 * CellWidth, my = 0.5 * CellHeight
        For pass = 0 To 1
            Dim fill As Integer() = Nothing
            If pass = 1 Then
                For c = 1 To cells
                    StaticStart(c) += StaticStart(c - 1)
                Next
                If StaticItems.Length < StaticStart(cells) Then StaticItems = New Integer(StaticStart(cells) - 1) {}
                fill = New Integer(cells - 1) {}
            End If
            For k = 0 To count - 1
                Dim c0 = ColumnOf(xmin(k) - mx), c1 = ColumnOf(xmax(k) + mx)
                Dim r0 = RowOf(ymin(k) - my), r1 = RowOf(ymax(k) + my)
                For row = r0 To r1
                    For col = c0 To c1
                        Dim c = row * Nx + col
                        If pass = 0 Then
                            StaticStart(c + 1) += 1
                        Else
                            StaticItems(StaticStart(c) + fill(c)) = k
                            fill(c) += 1
                        End If
                    Next
                Next
            Next
        Next
    End Sub
End Class
