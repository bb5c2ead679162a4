Option Strict On
Imports System.Globalization

''' <summary>
''' What this app can show, checked when a scene file is opened (the command line runs any valid
''' scene). A file may hold numbers the engine accepts but a screen cannot: a radius of 1e-300 m
''' gives an invisible ball of infinite density, a speed of 1e300 m/s an infinite kinetic energy.
''' Such a file is refused with the place and the limit, and the scene on screen is kept.
''' </summary>
Public Module SceneLimits
    ''' <summary>Largest distance of a body from the origin, and largest container side, m.</summary>
    Public Const MaxDistance As Double = 10000.0
    ''' <summary>Largest speed, m/s.</summary>
    Public Const MaxSpeed As Double = 1000000.0
    ''' <summary>Largest size of a body, m.</summary>
    Public Const MaxSize As Double = 1000.0
    ''' <summary>Largest mass, kg.</summary>
    Public Const MaxFileMass As Double = 1000000000.0

    ''' <summary>The first number in <paramref name="world"/> this app cannot show, named by its place ("bodies[3].radius: …"), or Nothing.</summary>
    Public Function Problem(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim p = Outside("world.width", world.Width, InputLimits.MinContainer / 100, MaxDistance, "m")
        If p IsNot Nothing Then Return p
        p = Outside("world.height", world.Height, InputLimits.MinContainer / 100, MaxDistance, "m")
        If p IsNot Nothing Then Return p
        Dim bodies = world.Bodies
        For i = 0 To bodies.Count - 1
            Dim place = "bodies[" & i.ToString(CultureInfo.InvariantCulture) & "]"
            Dim row = BodyRow.Capture(bodies(i))
            For Each size In row.SizeFields
                If p Is Nothing Then p = Outside(place & "." & size.Name, size.Metres, Math.Min(InputLimits.MinRadius, InputLimits.MinSide), MaxSize, "m")
            Next
            If p Is Nothing AndAlso Not row.IsFixed Then p = Outside(place & ".mass", row.Mass, InputLimits.MinMass, MaxFileMass, "kg")
            If p Is Nothing Then p = Outside(place & " position", row.Position.Length, 0, MaxDistance, "m from the origin")
            If p Is Nothing Then p = Outside(place & " speed", row.Velocity.Length, 0, MaxSpeed, "m/s")
            If p IsNot Nothing Then Return p
        Next
        Return Nothing
    End Function

    Private Function Outside(place As String, value As Double, min As Double, max As Double, unit As String) As String
        If value < min Then Return place & ": " & Units.Sig(value) & " " & unit & " is below the smallest this app shows, " & Units.Sig(min) & " " & unit
        If value > max OrElse Double.IsNaN(value) Then Return place & ": " & Units.Sig(value) & " " & unit & " is beyond the largest this app shows, " & Units.Sig(max) & " " & unit
        Return Nothing
    End Function
End Module
