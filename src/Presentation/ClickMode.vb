Option Strict On

''' <summary>What a left click on the canvas does.</summary>
Public Enum ClickMode
    ''' <summary>Aims the cue at a movable body (the normal mode).</summary>
    Move = 0
    ''' <summary>Removes the body or link under the cursor.</summary>
    Delete
    ''' <summary>Draws a ramp: press at one end, drag, let go at the other.</summary>
    Ramp
    ''' <summary>Joins two bodies, or a body and a fixed point, with a link: click one end, then the other.</summary>
    Link
    ''' <summary>Draws a polygon: click its corners one after another, then finish (first corner again, a double click, or Enter).</summary>
    Corners
    ''' <summary>Draws a liquid region: press at one corner, drag, let go at the opposite corner.</summary>
    Liquid
End Enum
