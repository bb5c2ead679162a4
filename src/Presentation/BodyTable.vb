Option Strict On

''' <summary>
''' The two tables under the canvas, as text: headers with units and the cells of one row, read by
''' the window's virtual-mode lists only for the rows on screen.
''' </summary>
Public Module BodyTable
    ''' <summary>Column headers of the circles table.</summary>
    Public ReadOnly Property CircleHeaders As IReadOnlyList(Of String) = {
        "Id", "Colour", "x (m)", "y (m)", "vx (m/s)", "vy (m/s)", "Speed (m/s)", "Mass (kg)", "Radius (m)", "Density (kg/m²)"}

    ''' <summary>Column headers of the rectangles table.</summary>
    Public ReadOnly Property RectangleHeaders As IReadOnlyList(Of String) = {
        "Id", "Colour", "x (m)", "y (m)", "vx (m/s)", "vy (m/s)", "Speed (m/s)", "Mass (kg)", "Width × height (m)", "Area (m²)"}

    ''' <summary>The cells of a circle's row.</summary>
    Public Function CircleRow(c As Circle) As String()
        If c Is Nothing Then Throw New ArgumentNullException(NameOf(c))
        Return {c.Id, If(c.Color, ""), Units.Num(c.Position.X), Units.Num(c.Position.Y),
                Units.Num(c.Velocity.X), Units.Num(c.Velocity.Y), Units.Num(c.Velocity.Length),
                If(c.IsFixed, "fixed (∞)", Units.Num(c.Mass)), Units.Num(c.Radius, 3),
                If(c.IsFixed, "—", Units.Num(c.Density))}
    End Function

    ''' <summary>The cells of a rectangle's row (rectangles are fixed: no velocity, infinite mass). x, y is the lower-left corner.</summary>
    Public Function RectangleRow(r As Rectangle) As String()
        If r Is Nothing Then Throw New ArgumentNullException(NameOf(r))
        Return {r.Id, If(r.Color, ""), Units.Num(r.Position.X), Units.Num(r.Position.Y),
                "0.00", "0.00", "0.00", "fixed (∞)", Units.Num(r.Width) & " × " & Units.Num(r.Height), Units.Num(r.Area)}
    End Function
End Module
