Option Strict On

''' <summary>What circles and rectangles share: an id that every output names them by, and a colour for the app.</summary>
Public MustInherit Class Shape
    ''' <summary>Unique in its world; assigned by <see cref="World.Add"/> when left empty.</summary>
    Public Property Id As String

    ''' <summary>How the app draws the body, "#rrggbb", or Nothing to let the app choose.</summary>
    Public Property Color As String

    ''' <summary>A fixed body never moves, feels no gravity and has infinite mass.</summary>
    Public MustOverride ReadOnly Property IsFixed As Boolean

    ''' <summary>Area in m².</summary>
    Public MustOverride ReadOnly Property Area As Double
End Class
