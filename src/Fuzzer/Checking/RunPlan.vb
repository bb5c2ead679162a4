Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>How long a scene runs and how it is sampled: what the command line's --time and --sample say.</summary>
    Friend NotInheritable Class RunPlan
        ''' <param name="time">simulated time T, s</param>
        ''' <param name="sample">sampling interval S, s</param>
        ''' <param name="secondSample">the event solver's second sampling interval, s (0: no second run)</param>
        ''' <param name="cap">wall-clock seconds one run may take</param>
        Friend Sub New(time As Double, sample As Double, secondSample As Double, cap As Double)
            If Not (time > 0) OrElse Not (sample > 0) OrElse Not (cap > 0) OrElse secondSample < 0 Then Throw New ArgumentOutOfRangeException(NameOf(time), "times must be positive")
            Me.Time = time
            Me.Sample = sample
            Me.SecondSample = secondSample
            Me.Cap = cap
        End Sub

        Friend ReadOnly Property Time As Double
        Friend ReadOnly Property Sample As Double
        Friend ReadOnly Property SecondSample As Double
        Friend ReadOnly Property Cap As Double

        ''' <summary>The same plan for a shorter (or longer) run.</summary>
        Friend Function WithTime(t As Double) As RunPlan
            Return New RunPlan(t, Sample, SecondSample, Cap)
        End Function

        Public Overrides Function ToString() As String
            Dim inv = CultureInfo.InvariantCulture
            Return "T = " & Time.ToString("R", inv) & " s, S = " & Sample.ToString("R", inv) & " s" &
                If(SecondSample > 0, " and " & SecondSample.ToString("R", inv) & " s", "") & ", cap " & Cap.ToString("R", inv) & " s"
        End Function
    End Class
End Namespace
