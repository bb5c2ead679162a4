Option Strict On

''' <summary>What a left click on a body does.</summary>
Public Enum ClickMode
    ''' <summary>Aims the cue at a movable circle (the normal mode).</summary>
    Move = 0
    ''' <summary>Removes the body under the cursor.</summary>
    Delete
End Enum
