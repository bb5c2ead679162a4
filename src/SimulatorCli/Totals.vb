Option Strict On

''' <summary>The totals that the summary and the totals CSV report, as cli.md defines them.</summary>
Friend Module Totals
    ''' <summary>
    ''' Potential energy, J: m·g·y of each movable body's centre of mass (y = 0 at the floor), plus
    ''' ½·k·extension² of each spring (both from <see cref="World.PotentialEnergy"/>), once, for both outputs.
    ''' </summary>
    Friend Function PotentialEnergy(world As World) As Double
        Return world.PotentialEnergy()
    End Function
End Module
