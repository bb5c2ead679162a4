Option Strict On

''' <summary>How a damped spring returns to equilibrium (see <see cref="DampedOscillator"/>).</summary>
Public Enum DampingRegime
    ''' <summary>γ &lt; ω (including no damping): it oscillates, the swings shrinking by e^(−γt).</summary>
    Underdamped
    ''' <summary>γ = ω: the quickest return without overshooting more than once.</summary>
    Critical
    ''' <summary>γ &gt; ω: it creeps back, crossing equilibrium at most once.</summary>
    Overdamped
End Enum
