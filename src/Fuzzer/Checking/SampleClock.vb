Option Strict On

Namespace Checking
    ''' <summary>
    ''' When a run reads the state, exactly as the command line's run does: t = k·S (each a product, not a
    ''' running sum) while below T, then T itself; a k·S within 1e-9·S of T counts as T. A run that advances
    ''' to these times, and only these, is the run the command line shows.
    ''' </summary>
    Friend Module SampleClock
        ''' <summary>0, S, 2S, … and T, for a run of <paramref name="total"/> s sampled every <paramref name="sample"/> s.</summary>
        Friend Iterator Function Times(total As Double, sample As Double) As IEnumerable(Of Double)
            Dim k = 0L
            Do
                Dim t = k * sample
                If t >= total - sample * 0.000000001 Then Exit Do
                Yield t
                k += 1
            Loop
            Yield total
        End Function
    End Module
End Namespace
