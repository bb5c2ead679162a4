Option Strict On

''' <summary>
''' The pool cue: the teacher pulls back from a ball and lets go. The impulse points from the
''' cursor to the ball's centre and grows in proportion to the pull, up to a limit; the ball gains
''' Δv = J / m, so the same pull moves a heavier ball less (F = ma integrated over the push).
''' </summary>
Public Module CueShot
    ''' <summary>Impulse per metre of pull, N·s/m.</summary>
    Public Const ImpulsePerMetre As Double = 4.0
    ''' <summary>Largest impulse, N·s.</summary>
    Public Const MaxImpulse As Double = 40.0

    ''' <summary>The impulse (N·s) a pull from <paramref name="centre"/> back to <paramref name="cursor"/> (both m) gives.</summary>
    Public Function ImpulseFor(centre As Vector, cursor As Vector) As Vector
        Dim pull = centre - cursor
        Dim j = pull * ImpulsePerMetre
        Dim size = j.Length
        If size > MaxImpulse Then j = j * (MaxImpulse / size)
        Return j
    End Function
End Module
