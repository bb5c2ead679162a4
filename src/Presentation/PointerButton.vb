Option Strict On

''' <summary>The mouse button a pointer event came from; the window translates its own enum into this one.</summary>
Public Enum PointerButton
    ''' <summary>No button (a plain move).</summary>
    None = 0
    ''' <summary>Places, deletes, or aims the cue.</summary>
    Left
    ''' <summary>Drags a body.</summary>
    Right
    ''' <summary>Pans the view (a drag), or follows a body (a click).</summary>
    Middle
End Enum
