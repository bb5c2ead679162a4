Option Strict On

''' <summary>What the Export menu writes.</summary>
Public Enum ExportKind
    ''' <summary>The Bodies table as CSV.</summary>
    BodiesCsv
    ''' <summary>The collision log as CSV.</summary>
    LogCsv
    ''' <summary>The series of the graph on show as CSV.</summary>
    SeriesCsv
    ''' <summary>The graph on show as a PNG picture.</summary>
    GraphPng
    ''' <summary>The canvas as a PNG picture.</summary>
    CanvasPng
End Enum
