Option Strict On

''' <summary>What ends a constrained group's motion at one of its constraints.</summary>
Friend Enum ConstraintEvent
    ''' <summary>Nothing yet.</summary>
    None
    ''' <summary>A taut string goes slack or a contact lifts off: its force falls to zero.</summary>
    Slackens
    ''' <summary>A contact leaves the face or corner it was on (a box slides off a table's edge).</summary>
    Leaves
    ''' <summary>A slack string (or a rod the others implied) reaches its length.</summary>
    Snaps
    ''' <summary>A contact touching without pressing is pressed in (by a slop).</summary>
    Presses
    ''' <summary>A contact touching without pressing opens clear.</summary>
    Opens
    ''' <summary>A contact sliding with friction stops sliding.</summary>
    Stops
    ''' <summary>A contact sticking by friction needs more than μs times its push: it starts to slide.</summary>
    Slips
End Enum
