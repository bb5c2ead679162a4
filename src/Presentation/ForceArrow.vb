Option Strict On

''' <summary>One arrow of a free-body diagram on the canvas: from <see cref="Start"/> to <see cref="Tip"/> (m), labelled "N 19.6 N".</summary>
Public NotInheritable Class ForceArrow
    ''' <summary>An arrow of <paramref name="kind"/> from <paramref name="start"/> to <paramref name="tip"/> (m), with <paramref name="label"/>.</summary>
    Public Sub New(kind As ForceKind, start As Vector, tip As Vector, label As String)
        Me.Kind = kind
        Me.Start = start
        Me.Tip = tip
        Me.Label = label
    End Sub

    ''' <summary>Which force.</summary>
    Public ReadOnly Property Kind As ForceKind
    ''' <summary>Where it starts: the body's centre of mass, m.</summary>
    Public ReadOnly Property Start As Vector
    ''' <summary>Its tip, m: the start plus the force times the diagram's metres per newton.</summary>
    Public ReadOnly Property Tip As Vector
    ''' <summary>Its symbol and size, "W 14.7 N".</summary>
    Public ReadOnly Property Label As String
End Class
