Option Strict On

''' <summary>
''' One of the tables under the canvas: its tab's title, its column headers (with units), which
''' bodies it lists, and the cells of a row. A new kind of body gets a table here and is listed in
''' <see cref="All"/>; the window makes one tab per table.
''' </summary>
Public NotInheritable Class BodyTable
    Private ReadOnly _lists As Func(Of Shape, Boolean)
    Private ReadOnly _cells As Func(Of BodyRow, String())

    Private Sub New(title As String, headers As String(), tip As String, lists As Func(Of Shape, Boolean), cells As Func(Of BodyRow, String()))
        Me.Title = title
        Me.Headers = headers
        Me.Tip = tip
        _lists = lists
        _cells = cells
    End Sub

    ''' <summary>The tab's title.</summary>
    Public ReadOnly Property Title As String
    ''' <summary>Column headers, with units.</summary>
    Public ReadOnly Property Headers As IReadOnlyList(Of String)
    ''' <summary>What the columns hold, in words (the headers are kept short so that every column shows at once).</summary>
    Public ReadOnly Property Tip As String

    ''' <summary>Whether this table lists the body.</summary>
    Public Function Lists(body As Shape) As Boolean
        Return _lists(body)
    End Function

    ''' <summary>The cells of one row, one per header.</summary>
    Public Function Cells(row As BodyRow) As String()
        Return _cells(row)
    End Function

    ''' <summary>
    ''' Every circle, movable and fixed. Its headers are short (|v| the speed, m the mass, r the radius,
    ''' ρ the density), so that all ten columns show at once at 192 dpi with large fonts; the tip says
    ''' what they are.
    ''' </summary>
    Public Shared ReadOnly Property Circles As New BodyTable("Circles",
        {"Id", "Colour", "x (m)", "y (m)", "vx (m/s)", "vy (m/s)", SpeedHeader, MassHeader, RadiusHeader, "ρ (kg/m²)"},
        "x, y: the centre (m); vx, vy: the velocity and |v| the speed (m/s); m: the mass (kg); r: the radius (m); " &
        "ρ: the density, mass per area (kg/m²). A ball takes no friction.",
        Function(b) TypeOf b Is Circle,
        Function(r) {r.Id, ColourCell(r), Units.Sig(r.Position.X), Units.Sig(r.Position.Y),
                     Units.Sig(r.Velocity.X), Units.Sig(r.Velocity.Y), Units.Sig(r.Velocity.Length),
                     If(r.IsFixed, "fixed", Units.Sig(r.Mass)), Units.Sig(r.Size.X),
                     If(r.IsFixed, "—", Units.Sig(r.Mass / r.Area))})

    ''' <summary>
    ''' Every rectangle (fixed: no velocity, no finite mass). x, y is the lower-left corner. Its headers
    ''' are short (w × h its size, A its area), so that all twelve columns show at once at 192 dpi with
    ''' large fonts; the tip says what they are.
    ''' </summary>
    Public Shared ReadOnly Property Rectangles As New BodyTable("Rectangles",
        {"Id", "Colour", "x (m)", "y (m)", "vx (m/s)", "vy (m/s)", SpeedHeader, MassHeader, SizeHeader, "A (m²)", KineticHeader, StaticHeader},
        "x, y: the lower-left corner (m); vx, vy: the velocity and |v| the speed (m/s); m: the mass (kg); " &
        "w × h: the width and height (m); A: the area (m²). " & FrictionTip,
        Function(b) TypeOf b Is Rectangle,
        Function(r) {r.Id, ColourCell(r), Units.Sig(r.Position.X), Units.Sig(r.Position.Y),
                     Units.Sig(r.Velocity.X), Units.Sig(r.Velocity.Y), Units.Sig(r.Velocity.Length),
                     If(r.IsFixed, "fixed", Units.Sig(r.Mass)), Units.Sig(r.Size.X) & " × " & Units.Sig(r.Size.Y), Units.Sig(r.Area),
                     KineticCell(r), StaticCell(r)})

    ''' <summary>
    ''' Every body of every kind, named in its Kind column; x, y is where its mass is centred (a ramp's
    ''' middle). Its headers are short (|v| the speed, m the mass), so that all twelve columns
    ''' show at once on a 1280-px-wide screen; the tip says what they are.
    ''' </summary>
    Public Shared ReadOnly Property Bodies As New BodyTable("Bodies",
        {"Id", "Colour", "Kind", "x (m)", "y (m)", "vx (m/s)", "vy (m/s)", SpeedHeader, MassHeader, "Size (m)", KineticHeader, StaticHeader},
        "x, y: where the body's mass is centred, a ramp's middle (m); vx, vy: the velocity and |v| the speed (m/s); m: the mass (kg); " &
        "Size: a ball's radius r, a box's or a polygon's width × height, a ramp's length (m). " & FrictionTip,
        Function(b) True,
        Function(r) {r.Id, ColourCell(r), r.KindLabel, Units.Sig(r.Centre.X), Units.Sig(r.Centre.Y),
                     Units.Sig(r.Velocity.X), Units.Sig(r.Velocity.Y), Units.Sig(r.Velocity.Length),
                     If(r.IsFixed, "fixed", Units.Sig(r.Mass)), r.SizeText, KineticCell(r), StaticCell(r)})

    ''' <summary>What the μk and μs columns hold, for the tables' tips.</summary>
    Public Const FrictionTip As String = "μk, μs: the coefficients of kinetic (sliding) and static friction of the body's surface; " &
        "(world): it takes the world's, set in the side panel. Double-click a cell to type a value."

    ''' <summary>The header of the speed's column, m/s (short: every column shows at once).</summary>
    Public Const SpeedHeader As String = "|v| (m/s)"
    ''' <summary>The header of the mass's column, kg.</summary>
    Public Const MassHeader As String = "m (kg)"
    ''' <summary>The header of a rectangle's width × height column, m.</summary>
    Public Const SizeHeader As String = "w × h (m)"
    ''' <summary>The header of a ball's radius's column, m.</summary>
    Public Const RadiusHeader As String = "r (m)"
    ''' <summary>The header of the column of a surface's own μk (no unit: a coefficient).</summary>
    Public Const KineticHeader As String = "μk"
    ''' <summary>The header of the column of a surface's own μs.</summary>
    Public Const StaticHeader As String = "μs"
    ''' <summary>What a friction cell says after the value a surface takes from the world (it has none of its own).</summary>
    Public Const WorldMark As String = " (world)"
    ''' <summary>A friction cell of a ball, which takes no friction.</summary>
    Public Const NoFrictionCell As String = "—"

    ''' <summary>The μk cell: its own ("0.6"), the world's it takes ("0.2 (world)"), or "—" for a ball.</summary>
    Public Shared Function KineticCell(row As BodyRow) As String
        If Not row.TakesFriction Then Return NoFrictionCell
        Return Units.Input(row.Kinetic) & If(row.OwnKinetic.HasValue, "", WorldMark)
    End Function

    ''' <summary>The μs cell: its own, its own μk's ("0.6 (= μk)"), the world's ("0.3 (world)"), or "—" for a ball.</summary>
    Public Shared Function StaticCell(row As BodyRow) As String
        If Not row.TakesFriction Then Return NoFrictionCell
        If row.OwnStatic.HasValue Then Return Units.Input(row.Static)
        Return Units.Input(row.Static) & If(row.OwnKinetic.HasValue, " (= μk)", WorldMark)
    End Function

    ''' <summary>
    ''' The colour cell of a body the canvas fills with the theme's fixed colour (its own colour is not
    ''' what shows): its swatch is that colour, its word why (not a colour's name: the theme chooses it).
    ''' </summary>
    Public Const FixedColourCell As String = "fixed"

    ''' <summary>The colour the body is drawn in: its own ("#e53935"), or <see cref="FixedColourCell"/>.</summary>
    Public Shared Function ColourCell(row As BodyRow) As String
        Return If(row.DrawnInFixedColour, FixedColourCell, row.Colour)
    End Function

    ''' <summary>The tables, in the order of their tabs.</summary>
    Public Shared ReadOnly Property All As IReadOnlyList(Of BodyTable) = {Circles, Rectangles, Bodies}
End Class
