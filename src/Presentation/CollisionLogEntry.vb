Option Strict On

''' <summary>
''' One row of the collision log: the two bodies, how many times in a row they met, their speeds
''' before and after, and the momentum and kinetic energy of the pair before and after (of the last
''' of those collisions). Against a wall, a fixed body or a carried ball only the moving circle
''' counts: the other has no finite mass, so momentum is not conserved there.
''' </summary>
Public NotInheritable Class CollisionLogEntry
    Private _text As String
    Private _cells As String()

    Private Sub New()
    End Sub

    ''' <summary>Simulated time of the (last) collision, s.</summary>
    Public Property Time As Double
    ''' <summary>Simulated time of the first collision this row counts, s.</summary>
    Public Property FirstTime As Double
    ''' <summary>How many collisions of this pair the row stands for.</summary>
    Public Property Repeats As Long = 1
    ''' <summary>The moving circle's id.</summary>
    Public Property AName As String
    ''' <summary>The other body's id, or wall:left and so on.</summary>
    Public Property BName As String
    ''' <summary>True when both are movable (and neither carried), so the pair's momentum is conserved.</summary>
    Public Property IsPair As Boolean
    ''' <summary>True when one of the two was being carried.</summary>
    Public Property WasCarried As Boolean
    ''' <summary>m/s</summary>
    Public Property ASpeedBefore As Double
    ''' <summary>m/s</summary>
    Public Property ASpeedAfter As Double
    ''' <summary>m/s (pairs only)</summary>
    Public Property BSpeedBefore As Double
    ''' <summary>m/s (pairs only)</summary>
    Public Property BSpeedAfter As Double
    ''' <summary>Momentum of the pair (or of A alone), kg·m/s.</summary>
    Public Property MomentumBefore As Vector
    ''' <summary>kg·m/s</summary>
    Public Property MomentumAfter As Vector
    ''' <summary>Kinetic energy of the pair (or of A alone), J.</summary>
    Public Property EnergyBefore As Double
    ''' <summary>J</summary>
    Public Property EnergyAfter As Double
    ''' <summary>When set, this row stands for this many collisions that were counted but not itemised.</summary>
    Public Property SkippedCount As Long

    ''' <summary>Reads a collision as the engine reported it.</summary>
    Public Shared Function FromRecord(record As CollisionRecord, dragged As Shape) As CollisionLogEntry
        Dim a = record.A
        Dim e As New CollisionLogEntry With {
            .Time = record.Time, .FirstTime = record.Time, .AName = a.Id, .BName = record.BName,
            .ASpeedBefore = record.AVelocityBefore.Length, .ASpeedAfter = record.AVelocityAfter.Length}
        Dim b = record.B
        Dim massA = a.Mass
        e.WasCarried = a Is dragged OrElse (b IsNot Nothing AndAlso b Is dragged)
        e.IsPair = b IsNot Nothing AndAlso Not b.IsFixed AndAlso Not e.WasCarried
        If e.IsPair Then
            e.BSpeedBefore = record.BVelocityBefore.Length
            e.BSpeedAfter = record.BVelocityAfter.Length
            e.MomentumBefore = record.AVelocityBefore * massA + record.BVelocityBefore * b.Mass
            e.MomentumAfter = record.AVelocityAfter * massA + record.BVelocityAfter * b.Mass
            e.EnergyBefore = 0.5 * massA * record.AVelocityBefore.LengthSquared + 0.5 * b.Mass * record.BVelocityBefore.LengthSquared
            e.EnergyAfter = 0.5 * massA * record.AVelocityAfter.LengthSquared + 0.5 * b.Mass * record.BVelocityAfter.LengthSquared
        Else
            e.MomentumBefore = record.AVelocityBefore * massA
            e.MomentumAfter = record.AVelocityAfter * massA
            e.EnergyBefore = 0.5 * massA * record.AVelocityBefore.LengthSquared
            e.EnergyAfter = 0.5 * massA * record.AVelocityAfter.LengthSquared
        End If
        Return e
    End Function

    ''' <summary>This collision as the latest of <paramref name="earlier"/>'s run of the same pair.</summary>
    Friend Function Following(earlier As CollisionLogEntry) As CollisionLogEntry
        Dim e = DirectCast(MemberwiseClone(), CollisionLogEntry)
        e._text = Nothing
        e._cells = Nothing
        e.FirstTime = earlier.FirstTime
        e.Repeats = earlier.Repeats + 1
        Return e
    End Function

    ''' <summary>A row standing for collisions that were counted but not itemised (a busy frame).</summary>
    Public Shared Function Skipped(time As Double, count As Long) As CollisionLogEntry
        Return New CollisionLogEntry With {.Time = time, .FirstTime = time, .SkippedCount = count}
    End Function

    ''' <summary>Fraction of the kinetic energy kept, 0 to 1 (1 when there was none to lose).</summary>
    Public ReadOnly Property EnergyKept As Double
        Get
            Return If(EnergyBefore > 0, EnergyAfter / EnergyBefore, 1.0)
        End Get
    End Property

    ''' <summary>The log's column headers, with units.</summary>
    Public Shared ReadOnly Property Headers As IReadOnlyList(Of String) = {
        "t (s)", "Bodies", "Speeds before → after (m/s)", "KE before → after (J)", "KE lost", "Momentum p before → after (kg·m/s)", "Note"}

    ''' <summary>A wall's name as a teacher says it: "floor", not "wall:bottom".</summary>
    Public Shared Function Spoken(name As String) As String
        Select Case name
            Case "wall:bottom" : Return "floor"
            Case "wall:top" : Return "ceiling"
            Case "wall:left" : Return "left wall"
            Case "wall:right" : Return "right wall"
            Case Else : Return name
        End Select
    End Function

    ''' <summary>The cells of this row, one per header (built once, on first use).</summary>
    Public Function Cells() As String()
        If _cells Is Nothing Then _cells = Format()
        Return CType(_cells.Clone(), String())
    End Function

    ''' <summary>The row as one sentence: "3 bounced 180 times on the floor (t = 0.12 to 6.00 s): …".</summary>
    Public ReadOnly Property Text As String
        Get
            If _text Is Nothing Then _text = Summary() & ": " & String.Join("; ", Cells().Skip(2).Where(Function(c) c.Length > 0))
            Return _text
        End Get
    End Property

    Private Function Summary() As String
        If SkippedCount > 0 Then Return "t = " & Units.Sig(Time, 4) & " s"
        Dim other = Spoken(BName)
        Dim what As String
        If BName.StartsWith("wall:", StringComparison.Ordinal) Then
            what = AName & " bounced " & TimesText() & If(BName = "wall:bottom", " on the ", " off the ") & other
        Else
            what = AName & " and " & other & " collided " & TimesText()
        End If
        Return what & If(Repeats > 1, " (t = " & Units.Sig(FirstTime, 4) & " to " & Units.Sig(Time, 4) & " s)", " (t = " & Units.Sig(Time, 4) & " s)")
    End Function

    Private Function TimesText() As String
        Return If(Repeats = 1, "once", Repeats.ToString(Globalization.CultureInfo.InvariantCulture) & " times")
    End Function

    Private Function Format() As String()
        Dim t = Units.Sig(Time, 4)
        If SkippedCount > 0 Then
            Return {t, "… " & SkippedCount.ToString(Globalization.CultureInfo.InvariantCulture) & " more collisions in this frame", "(counted, not listed)", "", "", "", ""}
        End If
        Dim other = Spoken(BName)
        Dim bodies = AName & " ↔ " & other & If(Repeats > 1, "  (" & TimesText() & ")", "")
        Dim speeds = If(IsPair,
            AName & ": " & Units.Sig(ASpeedBefore) & " → " & Units.Sig(ASpeedAfter) & ", " & BName & ": " & Units.Sig(BSpeedBefore) & " → " & Units.Sig(BSpeedAfter),
            AName & ": " & Units.Sig(ASpeedBefore) & " → " & Units.Sig(ASpeedAfter))
        Dim p = Units.SigPair(MomentumBefore) & " → " & Units.SigPair(MomentumAfter)
        Dim note = ""
        If Not IsPair Then note = AName & " only: p not conserved (" & If(WasCarried, "a carried ball", "the " & other) & " takes the impulse)"
        ' Rounding leaves about 1e-14 % "lost" at e = 1: below a twentieth of a percent reads 0.
        Dim lost = 100 * (1 - EnergyKept)
        If Math.Abs(lost) < 0.05 Then lost = 0
        Return {t, bodies, speeds, Units.Sig(EnergyBefore) & " → " & Units.Sig(EnergyAfter), Units.Sig(lost, 2) & "%", p, note}
    End Function
End Class
