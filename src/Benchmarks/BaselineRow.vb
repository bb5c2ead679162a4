Option Strict On

''' <summary>
''' One gas size measured with the engine at the baseline commit and with the engine as it is now, in
''' the same run (see <see cref="BaselineComparison"/>).
''' </summary>
Friend NotInheritable Class BaselineRow
    ''' <summary>Circles in the gas.</summary>
    Public Property BodyCount As Integer
    ''' <summary>The engine at the baseline commit: the median of its rounds.</summary>
    Public Property Before As BenchResult
    ''' <summary>The engine now: the median of its rounds.</summary>
    Public Property Now As BenchResult

    ''' <summary>
    ''' Each round's own ratio, now ÷ before, in round order: the two runs of a pair ran one right after
    ''' the other, so a pair's ratio is steadier than the machine's speed from round to round. A round
    ''' where either side failed has none.
    ''' </summary>
    Public ReadOnly Property PairRatios As New List(Of Double)

    ''' <summary>The median of <see cref="PairRatios"/>: the paired comparison's own figure; NaN when there are none.</summary>
    Public ReadOnly Property MedianPairRatio As Double
        Get
            Return If(PairRatios.Count = 0, Double.NaN, Statistics.Median(PairRatios))
        End Get
    End Property

    ''' <summary>Collisions per wall-clock second now ÷ before: above 1 the engine is faster now; NaN when either side has no figure.</summary>
    Public ReadOnly Property Ratio As Double
        Get
            If Before Is Nothing OrElse Now Is Nothing OrElse Not Before.Available OrElse Not Now.Available Then Return Double.NaN
            If Not (Before.CollisionsPerSecond > 0) OrElse Double.IsNaN(Now.CollisionsPerSecond) Then Return Double.NaN
            Return Now.CollisionsPerSecond / Before.CollisionsPerSecond
        End Get
    End Property
End Class
