Option Strict On

''' <summary>
''' One link's numbers at one moment, as the Links table shows them: copied with the bodies' rows,
''' so the table and the canvas of that moment agree.
''' </summary>
Public Structure LinkRow
    ''' <summary>The link's id.</summary>
    Public Property Id As String
    ''' <summary>"spring", "rod" or "string".</summary>
    Public Property KindName As String
    ''' <summary>A spring's stiffness k, N/m (0 for rods and strings).</summary>
    Public Property Stiffness As Double
    ''' <summary>The id of body A (always movable).</summary>
    Public Property EndA As String
    ''' <summary>The id of body B, or "" when end B is a fixed anchor.</summary>
    Public Property EndB As String
    ''' <summary>End B's fixed point, m, when <see cref="EndB"/> is "".</summary>
    Public Property Anchor As Vector
    ''' <summary>A rod's or string's length, or a spring's rest length, m.</summary>
    Public Property Length As Double
    ''' <summary>Distance between the ends minus the length, m (negative when compressed or slack).</summary>
    Public Property Extension As Double
    ''' <summary>The pull along the link, N (negative pushes the ends apart).</summary>
    Public Property Tension As Double

    ''' <summary>
    ''' The row of a link now. An extension or a pull at rounding noise (4.44×10⁻¹⁶ m beside a 2 m
    ''' length) is 0: beside the length for the extension; for the pull, beside the spring's pull at
    ''' that length, or the weight of the bodies at 10 m/s² for a rod or string.
    ''' </summary>
    Public Shared Function Capture(link As Link) As LinkRow
        If link Is Nothing Then Throw New ArgumentNullException(NameOf(link))
        Dim forceScale = If(link.Kind = LinkKind.Spring, link.Stiffness * Math.Max(link.Length, link.Distance),
                            10.0 * (link.A.Mass + If(link.B Is Nothing OrElse link.B.IsFixed, 0.0, link.B.Mass)))
        Return New LinkRow With {
            .Id = link.Id, .KindName = link.KindName, .Stiffness = link.Stiffness,
            .EndA = link.A.Id, .EndB = If(link.B Is Nothing, "", link.B.Id), .Anchor = link.Anchor,
            .Length = link.Length, .Extension = Units.AtNoise(link.Extension, Math.Max(link.Length, link.Distance)),
            .Tension = Units.AtNoise(link.Tension, forceScale)}
    End Function
End Structure
