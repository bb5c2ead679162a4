Option Strict On

''' <summary>
''' What the schedule keeps about one body: its next collision-type event and next cell crossing,
''' the counter that makes other bodies' predictions with it stale, its mode, and its grid cell
''' (with the cell's column and row, so no division finds them). Together, so an event touches one
''' or two cache lines of it rather than one per field.
''' </summary>
Friend Structure EventSlot
    ''' <summary>Time (s) of its next collision-type event, +∞ if none.</summary>
    Friend ColTime As Double
    ''' <summary>Time (s) its reference point next leaves its grid cell, +∞ if never.</summary>
    Friend CellTime As Double
    ''' <summary>Which way it leaves the cell: 0 −x, 1 +x, 2 −y, 3 +y.</summary>
    Friend CellDir As Integer
    Friend Kind As EventKind
    Friend Mode As BodyMode
    ''' <summary>The other body, obstacle or wall side of the collision-type event.</summary>
    Friend Other As Integer
    ''' <summary>The other body's <see cref="Count"/> when the event was predicted (a change since makes it stale).</summary>
    Friend OtherCount As Integer
    ''' <summary>Which face or corner of the obstacle.</summary>
    Friend Feature As Integer
    ''' <summary>Bumped whenever the body's motion changes; events remember it to detect staleness.</summary>
    Friend Count As Integer
    ''' <summary>Cell in the grid, or −1 for a body too large for it; its column and row.</summary>
    Friend Cell As Integer
    Friend Col As Integer
    Friend Row As Integer
End Structure
