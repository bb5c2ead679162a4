Option Strict On

''' <summary>What the linked event solver's next event is (<see cref="LinkedEventSolver"/>).</summary>
Friend Enum LinkedEventKind
    ''' <summary>A group's motion ends (a force falls to zero, a contact leaves its face, a string changes).</summary>
    GroupEnds
    ''' <summary>Two movable bodies meet.</summary>
    Pair
    ''' <summary>A body meets a side of the container.</summary>
    Wall
    ''' <summary>A body meets a fixed body.</summary>
    Fixed
End Enum
