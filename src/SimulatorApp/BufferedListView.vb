Option Strict On
Imports System.Windows.Forms

''' <summary>A ListView that paints through a back buffer, so the live tables do not flicker when refreshed.</summary>
Friend NotInheritable Class BufferedListView
    Inherits ListView

    Public Sub New()
        DoubleBuffered = True
        SetStyle(ControlStyles.OptimizedDoubleBuffer Or ControlStyles.AllPaintingInWmPaint, True)
        View = System.Windows.Forms.View.Details
        FullRowSelect = True
        GridLines = True
        VirtualMode = True
        HideSelection = False
    End Sub
End Class
