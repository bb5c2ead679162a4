Option Strict On

''' <summary>What <see cref="ConservativeAdvancement.FirstContact(IDistanceFunction, Double, Double, Double, Double, Double, Integer)"/> found.</summary>
Public Structure AdvancementResult
    ''' <summary>True when the distance falls to the tolerance in the interval; <see cref="Time"/> is then when.</summary>
    Public ReadOnly Property Found As Boolean

    ''' <summary>The first time (s) at which the distance is at the tolerance; +∞ when not <see cref="Found"/>.</summary>
    Public ReadOnly Property Time As Double

    ''' <summary>
    ''' Every time before this one (s) is proved clear. It is the interval's end when nothing was
    ''' found; less than that only when the step budget ran out, and the search can go on from here.
    ''' </summary>
    Public ReadOnly Property ClearUntil As Double

    ''' <summary>How many times the distance was evaluated.</summary>
    Public ReadOnly Property Evaluations As Integer

    ''' <summary>A result.</summary>
    Public Sub New(found As Boolean, time As Double, clearUntil As Double, evaluations As Integer)
        Me.Found = found
        Me.Time = time
        Me.ClearUntil = clearUntil
        Me.Evaluations = evaluations
    End Sub
End Structure
