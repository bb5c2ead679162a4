Option Strict On

''' <summary>
''' What the event-driven solver keeps about one body's next event, with the per-body fields every
''' event also reads (its counter, its cell and the cell's column and row): together, so an event
''' touches one or two cache lines of it rather than one per field.
''' </summary>
Friend Structure EventSlot
    ''' <summary>Time (s) of its next collision-type event (a collision, a slide's end, leaving an edge), +∞ if none.</summary>
    Friend ColTime As Double
    ''' <summary>Time (s) its centre next leaves its grid cell, +∞ if never.</summary>
    Friend CellTime As Double
    ''' <summary>Which way it leaves the cell: 0 −x, 1 +x, 2 −y, 3 +y.</summary>
    Friend CellDir As Integer
    Friend Kind As EventKind
    ''' <summary>The other body, fixed circle or rectangle of the collision-type event.</summary>
    Friend Other As Integer
    ''' <summary>The other body's <see cref="Count"/> when the event was predicted (a change since makes it stale).</summary>
    Friend OtherCount As Integer
    ''' <summary>Wall side, rectangle face or corner of the event.</summary>
    Friend Feature As Integer
    ''' <summary>Bumped whenever the body's motion changes; events remember it to detect staleness.</summary>
    Friend Count As Integer
    ''' <summary>Cell in the grid, or −1 for an oversized circle; its column and row (no division to find them).</summary>
    Friend Cell As Integer
    Friend Col As Integer
    Friend Row As Integer
End Structure
