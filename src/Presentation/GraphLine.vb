Option Strict On

''' <summary>One curve of a graph: its name for the key, its colour, and its points (x, y in the axes' units).</summary>
Public NotInheritable Class GraphLine
    Public Sub New(name As String, colour As Integer, points As IReadOnlyList(Of Vector), Optional dashed As Boolean = False)
        Me.Name = name
        Me.Colour = colour
        Me.Points = points
        Me.Dashed = dashed
    End Sub

    ''' <summary>What the key calls it ("KE (J)").</summary>
    Public ReadOnly Property Name As String
    ''' <summary>0xRRGGBB.</summary>
    Public ReadOnly Property Colour As Integer
    ''' <summary>In the order drawn.</summary>
    Public ReadOnly Property Points As IReadOnlyList(Of Vector)
    ''' <summary>Drawn dashed (a theory curve beside a measured one).</summary>
    Public ReadOnly Property Dashed As Boolean
End Class
