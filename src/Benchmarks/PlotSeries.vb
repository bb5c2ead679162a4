Option Strict On

''' <summary>
''' One curve of a plot: a name for the legend, a colour ("#rrggbb"), a marker shape (0 diamond,
''' 1 circle, 2 square; the same solver keeps its shape in every plot) and its points in order.
''' </summary>
Friend NotInheritable Class PlotSeries
    Public Sub New(name As String, color As String, points As IEnumerable(Of PlotPoint), Optional marker As Integer = 0)
        Me.Name = name
        Me.Color = color
        Me.Points = points.ToList()
        Me.Marker = marker
    End Sub

    Public ReadOnly Property Marker As Integer

    Public ReadOnly Property Name As String
    Public ReadOnly Property Color As String
    Public ReadOnly Property Points As IReadOnlyList(Of PlotPoint)
End Class
