Option Strict On

''' <summary>A motion that knows the energy its drag has removed (J) from its start to any later time, by its own closed form or integral.</summary>
Friend Interface IDissipatingMotion
    ''' <summary>Energy removed from <see cref="LinkedMotion.StartTime"/> to <paramref name="time"/> (s), J; never decreasing in time.</summary>
    Function Dissipated(time As Double) As Double
End Interface
