Option Strict On

''' <summary>How the event-driven solver lays its grid over the container and files the bodies in it.</summary>
Friend Module GridLayout
    ''' <summary>
    ''' How many bodies a cell should hold on average: bigger cells mean fewer crossings but more
    ''' pairs to test. Testing a whole cell's lanes at once (vectors) makes pairs cheap, so about 2;
    ''' one at a time (.NET Framework, Mono), about 1.2. Both measured on the elastic gas.
    ''' </summary>
    Friend Function BodiesPerCell(vectorScan As Boolean) As Double
        Return If(vectorScan, 2.0, 1.2)
    End Function

    ''' <summary>
    ''' Where bodies will pile (see <see cref="WillPile"/>), cells are at most this many of the largest
    ''' gridded diameters wide, m/m: about two bodies to a cell in a close-packed pile. Measured on the
    ''' Galton board (balls spread over a large board, piling in its bins) and the gas under gravity.
    ''' </summary>
    Friend Const PileCellDiameters As Double = 3.0

    ''' <summary>
    ''' Cells holding about <paramref name="perCell"/> bodies each (few crossings, few neighbours),
    ''' never narrower than the largest gridded diameter (nor, where they will pile, wider than <see cref="PileCellDiameters"/> of it). Bodies reaching more than four times the median
    ''' from their reference point are "oversized": kept out of the grid and checked against every body, so one giant does not
    ''' make every cell huge. Every body is filed in its cell and published; every obstacle is listed
    ''' in the cells it can be touched from.
    ''' </summary>
    Friend Sub Lay(s As SolverState, perCell As Double)
        Dim b = s.Bodies
        Dim n = b.Count
        Dim limit = Double.PositiveInfinity
        If n > 0 Then
            Dim radii = New Double(n - 1) {}
            For k = 0 To n - 1
                radii(k) = b.Size(k).Reach
            Next
            Array.Sort(radii)
            limit = 4 * radii(n \ 2)
        End If
        If s.Oversized.Length < n Then s.Oversized = New Integer(n - 1) {}
        Dim rMax = 0.0
        s.OversizedCount = 0
        For i = 0 To n - 1
            If b.Size(i).Reach > limit Then
                s.Oversized(s.OversizedCount) = i
                s.OversizedCount += 1
            Else
                rMax = Math.Max(rMax, b.Size(i).Reach)
            End If
        Next
        s.RMax = rMax
        Dim gridded = Math.Max(1, n - s.OversizedCount)
        Dim cell = Math.Sqrt(perCell * s.Width * s.Height / gridded)
        ' Piling bodies gather where gravity pulls them, up to close packing, however thinly they are
        ' spread over the container on average: a cell sized for the average would hold tens of them there.
        If rMax > 0 AndAlso WillPile(s) Then cell = Math.Min(cell, PileCellDiameters * 2 * rMax)
        cell = Math.Max(2 * rMax * (1 + 1.0E-9), cell)
        s.Grid.Layout(s.Width, s.Height, cell, n, 4 * n + 64)
        For i = 0 To n - 1
            If b.Size(i).Reach > limit Then
                b.Slot(i).Cell = -1
            Else
                b.Slot(i).Col = s.Grid.ColumnOf(b.Motion(i).Px)
                b.Slot(i).Row = s.Grid.RowOf(b.Motion(i).Py)
                b.Slot(i).Cell = b.Slot(i).Row * s.Grid.Nx + b.Slot(i).Col
                s.Grid.Insert(i, b.Slot(i).Cell)
                s.Publish(i)
            End If
        Next
        Dim o = s.Obstacles
        Dim x0 = New Double(o.Count - 1) {}, y0 = New Double(o.Count - 1) {}, x1 = New Double(o.Count - 1) {}, y1 = New Double(o.Count - 1) {}
        For k = 0 To o.Count - 1
            o.Bounds(k, x0(k), y0(k), x1(k), y1(k))
        Next
        s.Grid.SetStatics(x0, y0, x1, y1, o.Count)
    End Sub

    ''' <summary>
    ''' Whether the movable bodies will gather in piles, so that cells sized for their average spread
    ''' would be crowded where they gather. Under gravity, always when collisions lose energy (e &lt; 1):
    ''' the bodies end at rest on the floor. With e = 1 nothing is lost, and each body can climb to the
    ''' height its energy allows, h = y + v² / (2 g) above the floor gravity pulls towards. When that
    ''' height is on average at least the container's, they fill it like a gas (fast bodies in small
    ''' cells would only cost cell crossings); below it, they gather in a dense layer at the bottom.
    ''' </summary>
    Private Function WillPile(s As SolverState) As Boolean
        If s.G = 0 Then Return False
        If s.E < 1 Then Return True
        Dim b = s.Bodies
        Dim g = Math.Abs(s.G)
        Dim climb = 0.0 ' m, summed over the bodies
        For i = 0 To b.Count - 1
            Dim x, y, vx, vy As Double
            b.Motion(i).StateAt(s.Now, x, y, vx, vy)
            climb += If(s.G > 0, y, s.Height - y) + (vx * vx + vy * vy) / (2 * g)
        Next
        Return Not (climb >= s.Height * b.Count) ' written so that NaN piles (the layout measured on piles)
    End Function
End Module
