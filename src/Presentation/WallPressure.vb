Option Strict On

''' <summary>
''' The pressure on the container's walls measured as a gauge would: the impulses the walls give
''' (Σ |Δp| = Σ m |v after − v before| over the wall collisions) divided by the walls' length and
''' the time, P = Σ |Δp| / (perimeter × t), N/m. Readings are taken over successive intervals of
''' <see cref="ReadingSeconds"/> (at least) of simulated time; the average since the start and its
''' standard error come from them. At most <see cref="MaxReadings"/> readings are kept for the
''' graph; the average counts every one.
''' </summary>
Public NotInheritable Class WallPressure
    ''' <summary>Readings kept for the graph.</summary>
    Public Const MaxReadings As Integer = 2000

    Private ReadOnly _readings As New List(Of PressureReading)
    Private _start As Double
    Private _intervalStart As Double
    Private _intervalImpulse As Double
    Private _impulse As Double
    Private _sum As Double
    Private _sumSquares As Double
    Private _idealSum As Double
    Private _readingCount As Integer
    Private _kTSum As Double
    Private _kTSamples As Integer

    ''' <param name="start">simulated time the measurement starts, s</param>
    ''' <param name="perimeter">length of the walls, m</param>
    ''' <param name="readingSeconds">simulated time over which each reading is taken, s</param>
    Public Sub New(start As Double, perimeter As Double, Optional readingSeconds As Double = 1.0)
        If Not (perimeter > 0) Then Throw New ArgumentOutOfRangeException(NameOf(perimeter))
        If Not (readingSeconds > 0) Then Throw New ArgumentOutOfRangeException(NameOf(readingSeconds))
        _start = start
        _intervalStart = start
        Me.Perimeter = perimeter
        Me.ReadingSeconds = readingSeconds
    End Sub

    ''' <summary>m</summary>
    Public ReadOnly Property Perimeter As Double
    ''' <summary>s</summary>
    Public ReadOnly Property ReadingSeconds As Double

    ''' <summary>The readings kept, oldest first.</summary>
    Public ReadOnly Property Readings As IReadOnlyList(Of PressureReading)
        Get
            Return _readings
        End Get
    End Property

    ''' <summary>Σ |Δp| on the walls since the start, N·s.</summary>
    Public ReadOnly Property TotalImpulse As Double
        Get
            Return _impulse
        End Get
    End Property

    ''' <summary>Takes one collision: a wall's adds m |Δv| to the impulse, others are ignored.</summary>
    Public Sub Collided(record As CollisionRecord)
        If record.B IsNot Nothing OrElse record.Wall = WallSide.None OrElse record.A Is Nothing Then Return
        Dim dp = record.A.Mass * (record.AVelocityAfter - record.AVelocityBefore).Length
        If Double.IsNaN(dp) OrElse Double.IsInfinity(dp) Then Return
        _impulse += dp
        _intervalImpulse += dp
    End Sub

    ''' <summary>
    ''' Called as time goes on with the gas's kT (J) and N k T / A (N/m) at <paramref name="time"/>
    ''' (s); closes a reading when its interval is over. Returns whether one was closed.
    ''' </summary>
    Public Function Advance(time As Double, kT As Double, idealPressure As Double) As Boolean
        If Not Double.IsNaN(kT) Then
            _kTSum += kT
            _kTSamples += 1
        End If
        Dim span = time - _intervalStart
        If span < ReadingSeconds Then Return False
        Dim p = _intervalImpulse / (Perimeter * span)
        _readingCount += 1
        _sum += p
        _sumSquares += p * p
        If Not Double.IsNaN(idealPressure) Then _idealSum += idealPressure
        If _readings.Count = MaxReadings Then _readings.RemoveAt(0)
        _readings.Add(New PressureReading(time, p, idealPressure))
        _intervalStart = time
        _intervalImpulse = 0
        Return True
    End Function

    ''' <summary>Simulated time measured so far (to the end of the last reading), s.</summary>
    Public ReadOnly Property MeasuredSeconds As Double
        Get
            Return _intervalStart - _start
        End Get
    End Property

    ''' <summary>Σ |Δp| / (perimeter × t) from the start to the end of the last reading, N/m (NaN before the first reading).</summary>
    Public ReadOnly Property Average As Double
        Get
            If _readingCount = 0 Then Return Double.NaN
            Return (_impulse - _intervalImpulse) / (Perimeter * MeasuredSeconds)
        End Get
    End Property

    ''' <summary>The standard error of <see cref="Average"/> from the scatter of the readings, N/m (NaN with fewer than two).</summary>
    Public ReadOnly Property StandardError As Double
        Get
            If _readingCount < 2 Then Return Double.NaN
            Dim mean = _sum / _readingCount
            Dim variance = Math.Max(0.0, (_sumSquares - _readingCount * mean * mean) / (_readingCount - 1))
            Return Math.Sqrt(variance / _readingCount)
        End Get
    End Property

    ''' <summary>The mean of N k T / A over the readings, N/m.</summary>
    Public ReadOnly Property AverageIdeal As Double
        Get
            Return If(_readingCount = 0, Double.NaN, _idealSum / _readingCount)
        End Get
    End Property

    ''' <summary>The mean kT offered so far, J.</summary>
    Public ReadOnly Property AverageKT As Double
        Get
            Return If(_kTSamples = 0, Double.NaN, _kTSum / _kTSamples)
        End Get
    End Property

    ''' <summary>Readings closed since the start.</summary>
    Public ReadOnly Property ReadingCount As Integer
        Get
            Return _readingCount
        End Get
    End Property
End Class
