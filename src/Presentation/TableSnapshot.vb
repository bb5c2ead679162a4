Option Strict On

''' <summary>
''' The tables and the totals line at one moment. The presenter takes one after every change it
''' makes and about ten times a second while time runs; the window shows only this, so the rows and
''' the totals always describe the same moment (and, when paused, the same state the canvas draws).
''' </summary>
Public NotInheritable Class TableSnapshot
    Private ReadOnly _rows As List(Of BodyRow)()
    Private ReadOnly _links As List(Of LinkRow)

    Private Sub New(time As Double, totals As IReadOnlyList(Of String), rows As List(Of BodyRow)(), links As List(Of LinkRow), fastest As Double)
        Me.Time = time
        Me.Totals = totals
        _rows = rows
        _links = links
        Me.FastestSpeed = fastest
    End Sub

    ''' <summary>Simulated time of the snapshot, s.</summary>
    Public ReadOnly Property Time As Double
    ''' <summary>The items of the totals line (each kept on one line, with its unit).</summary>
    Public ReadOnly Property Totals As IReadOnlyList(Of String)
    ''' <summary>The largest speed of a movable body, m/s.</summary>
    Public ReadOnly Property FastestSpeed As Double

    ''' <summary>Rows in table <paramref name="table"/> (an index into <see cref="BodyTable.All"/>).</summary>
    Public Function RowCount(table As Integer) As Integer
        Return If(table >= 0 AndAlso table < _rows.Length, _rows(table).Count, 0)
    End Function

    ''' <summary>The numbers of one row.</summary>
    Public Function Row(table As Integer, index As Integer) As BodyRow
        Return _rows(table)(index)
    End Function

    ''' <summary>The cells of one row, as shown.</summary>
    Public Function Cells(table As Integer, index As Integer) As String()
        Return BodyTable.All(table).Cells(_rows(table)(index))
    End Function

    ''' <summary>Rows in the Links table.</summary>
    Public ReadOnly Property LinkCount As Integer
        Get
            Return _links.Count
        End Get
    End Property

    ''' <summary>The numbers of one link's row.</summary>
    Public Function LinkRowAt(index As Integer) As LinkRow
        Return _links(index)
    End Function

    ''' <summary>The cells of one link's row, as shown.</summary>
    Public Function LinkCells(index As Integer) As String()
        Return LinkTable.Cells(_links(index))
    End Function

    ''' <summary>Copies the world's state now.</summary>
    Friend Shared Function Take(world As World, collisions As Long) As TableSnapshot
        Dim tables = BodyTable.All
        Dim rows(tables.Count - 1) As List(Of BodyRow)
        For t = 0 To tables.Count - 1
            rows(t) = New List(Of BodyRow)
        Next
        ' Rounding noise is judged beside the scene's own scales: its size, and the fastest of its
        ' bodies or the speed a fall across the box would give, whichever is more.
        Dim lengthScale = Math.Max(world.Width, world.Height)
        Dim speedScale = Math.Sqrt(Math.Max(1.0, Math.Abs(world.Gravity)) * lengthScale)
        For Each b In world.Bodies
            If Not b.IsFixed Then speedScale = Math.Max(speedScale, b.Velocity.Length)
        Next
        Dim fastest = 0.0
        For Each b In world.Bodies
            Dim row = BodyRow.Capture(b, lengthScale, speedScale)
            row.Kinetic = world.KineticFrictionOf(b)
            row.Static = world.StaticFrictionOf(b)
            If Not b.IsFixed Then fastest = Math.Max(fastest, row.Velocity.Length)
            For t = 0 To tables.Count - 1
                If tables(t).Lists(b) Then rows(t).Add(row)
            Next
        Next
        Dim links = world.Links.Select(AddressOf LinkRow.Capture).ToList()
        Return New TableSnapshot(world.Time, TotalsOf(world, collisions, speedScale), rows, links, fastest)
    End Function

    Private Shared Function TotalsOf(world As World, collisions As Long, speedScale As Double) As IReadOnlyList(Of String)
        ' Σp at rounding noise beside the bodies' masses at the scene's speed is 0 (two equal balls meeting head-on).
        Dim momentumScale = world.Movables.Sum(Function(b) b.Mass) * speedScale
        Dim raw = world.Momentum()
        Dim p = New Vector(Units.AtNoise(raw.X, momentumScale), Units.AtNoise(raw.Y, momentumScale))
        Dim ke = world.KineticEnergy()
        Dim pe = world.PotentialEnergy()
        Return {
            Item("t = " & Units.Quantity(world.Time, "s", 4)),
            Item("Σp = " & Units.SigPair(p) & " kg·m/s"),
            Item("|Σp| = " & Units.Quantity(p.Length, "kg·m/s")),
            Item("ΣKE = " & Units.Quantity(ke, "J")),
            Item("ΣPE = " & Units.Quantity(pe, "J")),
            Item("KE + PE = " & Units.Quantity(ke + pe, "J")),
            Item("collisions: " & collisions.ToString(Globalization.CultureInfo.InvariantCulture))}
    End Function

    ''' <summary>One item of the totals line, never broken across lines.</summary>
    Private Shared Function Item(text As String) As String
        Return text.Replace(" "c, Units.Nbsp)
    End Function
End Class
