Option Strict On

''' <summary>A part of a frame over a timed run, ms: the median, the 95th percentile and the worst frame.</summary>
Friend NotInheritable Class FrameTimes
    Public Property Median As Double = Double.NaN
    Public Property P95 As Double = Double.NaN
    Public Property Worst As Double = Double.NaN

    ''' <summary>True when all three were read.</summary>
    Public ReadOnly Property Complete As Boolean
        Get
            Return Not (Double.IsNaN(Median) OrElse Double.IsNaN(P95) OrElse Double.IsNaN(Worst))
        End Get
    End Property
End Class
