Option Strict On

''' <summary>The Links tab under the canvas: one row per spring, rod or string, with its ends, length, stretch and pull.</summary>
Public Module LinkTable
    ''' <summary>The tab's title.</summary>
    Public Const Title As String = "Links"

    ''' <summary>Column headers, with units.</summary>
    Public ReadOnly Property Headers As IReadOnlyList(Of String) =
        {"Id", "Kind", "End A", "End B", "Length (m)", "Extension (m)", "Tension (N)"}

    ''' <summary>The cells of one row, one per header. A spring's kind names its stiffness; an anchor's end names its point.</summary>
    Public Function Cells(row As LinkRow) As String()
        Dim kind = If(row.KindName = "spring", "spring, k " & Units.Quantity(row.Stiffness, "N/m"), row.KindName)
        Dim endB = If(row.EndB.Length > 0, row.EndB, "anchor " & Units.SigPair(row.Anchor))
        Return {row.Id, kind, row.EndA, endB, Units.Sig(row.Length), Units.Sig(row.Extension), Units.Sig(row.Tension)}
    End Function
End Module
