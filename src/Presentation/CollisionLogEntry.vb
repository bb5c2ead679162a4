Option Strict On

''' <summary>
''' One line of the collision log: the two bodies, their speeds before and after, and the momentum
''' and kinetic energy of the pair before and after. Against a wall, a fixed body or a dragged one,
''' only the moving circle counts: the other has no (finite) mass, so momentum is not conserved there.
''' </summary>
Public NotInheritable Class CollisionLogEntry
    Private _text As String

    Private Sub New()
    End Sub

    ''' <summary>Simulated time, s.</summary>
    Public Property Time As Double
    ''' <summary>The moving circle's id.</summary>
    Public Property AName As String
    ''' <summary>The other body's id, or wall:left and so on.</summary>
    Public Property BName As String
    ''' <summary>True when both are movable circles, so the pair's momentum is conserved.</summary>
    Public Property IsPair As Boolean
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
    ''' <summary>When set, this line stands for this many collisions that were counted but not itemised.</summary>
    Public Property SkippedCount As Long

    ''' <summary>Reads a collision as the engine reported it.</summary>
    Public Shared Function FromRecord(record As CollisionRecord, draggedCircle As Circle) As CollisionLogEntry
        Dim a = record.A
        Dim e As New CollisionLogEntry With {
            .Time = record.Time, .AName = a.Id, .BName = record.BName,
            .ASpeedBefore = record.AVelocityBefore.Length, .ASpeedAfter = record.AVelocityAfter.Length}
        Dim b = TryCast(record.B, Circle)
        Dim massA = a.Mass
        e.IsPair = b IsNot Nothing AndAlso Not b.IsFixed AndAlso b IsNot draggedCircle AndAlso a IsNot draggedCircle
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

    ''' <summary>A line standing for collisions that were counted but not itemised (a busy frame).</summary>
    Public Shared Function Skipped(time As Double, count As Long) As CollisionLogEntry
        Return New CollisionLogEntry With {.Time = time, .SkippedCount = count}
    End Function

    ''' <summary>Fraction of the kinetic energy kept, 0 to 1 (1 when there was none to lose).</summary>
    Public ReadOnly Property EnergyKept As Double
        Get
            Return If(EnergyBefore > 0, EnergyAfter / EnergyBefore, 1.0)
        End Get
    End Property

    ''' <summary>The log's column headers, with units.</summary>
    Public Shared ReadOnly Property Headers As IReadOnlyList(Of String) = {
        "t (s)", "Bodies", "Speeds before → after (m/s)", "KE before → after (J)", "KE lost", "Momentum p before → after (kg·m/s)"}

    Private _cells As String()

    ''' <summary>The cells of this line, one per header (built once, on first use).</summary>
    Public Function Cells() As String()
        If _cells Is Nothing Then _cells = Format()
        Return CType(_cells.Clone(), String())
    End Function

    ''' <summary>The whole line as one string.</summary>
    Public ReadOnly Property Text As String
        Get
            If _text Is Nothing Then _text = String.Join("   ", Cells())
            Return _text
        End Get
    End Property

    Private Function Format() As String()
        Dim t = Units.Num(Time, 3)
        If SkippedCount > 0 Then
            Return {t, "… " & SkippedCount.ToString(Globalization.CultureInfo.InvariantCulture) & " more collisions in this frame", "(counted, not listed)", "", "", ""}
        End If
        Dim speeds = If(IsPair,
            AName & ": " & Units.Num(ASpeedBefore) & " → " & Units.Num(ASpeedAfter) & ", " & BName & ": " & Units.Num(BSpeedBefore) & " → " & Units.Num(BSpeedAfter),
            AName & ": " & Units.Num(ASpeedBefore) & " → " & Units.Num(ASpeedAfter))
        Dim p = Units.Pair(MomentumBefore) & " → " & Units.Pair(MomentumAfter)
        If Not IsPair Then p &= "  (" & AName & " only: " & BName & " is fixed, p not conserved)"
        Return {t, AName & " ↔ " & BName, speeds, Units.Num(EnergyBefore) & " → " & Units.Num(EnergyAfter), Units.Num(100 * (1 - EnergyKept), 0) & "%", p}
    End Function
End Class
