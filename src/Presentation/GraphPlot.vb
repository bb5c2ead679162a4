Option Strict On

''' <summary>
''' Everything a graph shows, in the units of its axes, for the window to draw: title, axis labels
''' with units, curves, the histogram's bars, and lines of notes (the numbers a teacher reads out).
''' </summary>
Public NotInheritable Class GraphPlot
    ''' <summary>The graph's title.</summary>
    Public Property Title As String = ""
    ''' <summary>The horizontal axis and its unit: "time t (s)".</summary>
    Public Property XLabel As String = ""
    ''' <summary>The vertical axis and its unit: "energy (J)".</summary>
    Public Property YLabel As String = ""
    ''' <summary>The curves, drawn in order.</summary>
    Public ReadOnly Property Lines As New List(Of GraphLine)
    ''' <summary>The histogram's bars (Nothing for a graph against time).</summary>
    Public Property Bars As SpeedHistogram
    ''' <summary>The bars' colour, 0xRRGGBB.</summary>
    Public Property BarColour As Integer = &H90A4AE
    ''' <summary>Lines of text shown with the graph.</summary>
    Public ReadOnly Property Notes As New List(Of String)
    ''' <summary>The lower end of the vertical axis when it must include 0 (energies, counts, pressures); NaN to fit the data.</summary>
    Public Property YFloor As Double = Double.NaN
    ''' <summary>What the graph has nothing to show about yet, or "" ("No movable bodies").</summary>
    Public Property EmptyText As String = ""

    ''' <summary>The smallest and largest x and y of the curves and bars.</summary>
    Public Function Bounds() As (XMin As Double, XMax As Double, YMin As Double, YMax As Double)
        Dim xmin = Double.PositiveInfinity, xmax = Double.NegativeInfinity
        Dim ymin = Double.PositiveInfinity, ymax = Double.NegativeInfinity
        For Each l In Lines
            For Each p In l.Points
                If Double.IsNaN(p.X) OrElse Double.IsNaN(p.Y) OrElse Double.IsInfinity(p.X) OrElse Double.IsInfinity(p.Y) Then Continue For
                xmin = Math.Min(xmin, p.X)
                xmax = Math.Max(xmax, p.X)
                ymin = Math.Min(ymin, p.Y)
                ymax = Math.Max(ymax, p.Y)
            Next
        Next
        If Bars IsNot Nothing Then
            xmin = Math.Min(xmin, Bars.Edges(0))
            xmax = Math.Max(xmax, Bars.Edges(Bars.Edges.Count - 1))
            ymin = Math.Min(ymin, 0)
            ymax = Math.Max(ymax, If(Bars.Counts.Count = 0, 0, Bars.Counts.Max()))
        End If
        If Not Double.IsNaN(YFloor) Then ymin = Math.Min(ymin, YFloor)
        Return (xmin, xmax, ymin, ymax)
    End Function
End Class
