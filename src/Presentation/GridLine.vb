Option Strict On

''' <summary>One line of the canvas grid, m: from <see cref="Start"/> to <see cref="[End]"/>, a metre line or a 10 cm one.</summary>
Public Structure GridLine
    ''' <param name="start">one end, m</param>
    ''' <param name="[end]">the other end, m</param>
    ''' <param name="major">a whole-metre line (drawn stronger)</param>
    Public Sub New(start As Vector, [end] As Vector, major As Boolean)
        Me.Start = start
        Me.End = [end]
        Me.Major = major
    End Sub

    ''' <summary>One end, m.</summary>
    Public ReadOnly Property Start As Vector
    ''' <summary>The other end, m.</summary>
    Public ReadOnly Property [End] As Vector
    ''' <summary>A whole-metre line.</summary>
    Public ReadOnly Property Major As Boolean
End Structure
