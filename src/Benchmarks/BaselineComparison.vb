Option Strict On
Imports System.Globalization

''' <summary>
''' The elastic gas with the engine before the event solver's restructure (the baseline commit, built
''' apart by scripts/bench.sh) beside the engine now, measured in the same run: each round runs both
''' at each size, one right after the other, so both meet much the same spell of a shared machine.
''' </summary>
Friend NotInheritable Class BaselineComparison
    ''' <summary>The gas sizes compared: the report's headline sizes.</summary>
    Public Shared ReadOnly Property Sizes As IReadOnlyList(Of Integer) = {1000, 10000}

    ''' <summary>The baseline commit (as the script passed it), or "" when none was given.</summary>
    Public Property Commit As String = ""
    ''' <summary>Why the comparison did not run, or a remark; "" when it ran.</summary>
    Public Property Note As String = ""
    ''' <summary>One row per size, in <see cref="Sizes"/> order.</summary>
    Public ReadOnly Property Rows As New List(Of BaselineRow)

    ''' <summary>The commit as the report names it: its first 7 hex digits.</summary>
    Public ReadOnly Property ShortCommit As String
        Get
            Return If(Commit.Length > 7, Commit.Substring(0, 7), Commit)
        End Get
    End Property

    ''' <summary>A comparison that did not run, and why.</summary>
    Public Shared Function NotRun(commit As String, note As String) As BaselineComparison
        Return New BaselineComparison With {.Commit = If(commit, ""), .Note = If(note, "")}
    End Function

    ''' <summary>
    ''' The rows from the rounds of both engines: <paramref name="nowRounds"/> and
    ''' <paramref name="beforeRounds"/> hold one list per round, each with one result per size in the
    ''' same order. Each side's row is its median round (<see cref="GasScaling.CombineRounds"/>), and a
    ''' size is matched by its N, not its place, so a side that lost a row cannot pair the wrong sizes.
    ''' </summary>
    Public Shared Function Combine(commit As String, nowRounds As IReadOnlyList(Of IReadOnlyList(Of BenchResult)),
                                   beforeRounds As IReadOnlyList(Of IReadOnlyList(Of BenchResult))) As BaselineComparison
        If nowRounds Is Nothing Then Throw New ArgumentNullException(NameOf(nowRounds))
        If beforeRounds Is Nothing Then Throw New ArgumentNullException(NameOf(beforeRounds))
        Dim now = GasScaling.CombineRounds(nowRounds)
        Dim before = GasScaling.CombineRounds(beforeRounds)
        Dim comparison As New BaselineComparison With {.Commit = If(commit, "")}
        For Each n In now.Select(Function(r) r.BodyCount).Concat(before.Select(Function(r) r.BodyCount)).Distinct().OrderBy(Function(x) x)
            Dim size = n
            Dim row As New BaselineRow With {
                .BodyCount = size,
                .Now = now.FirstOrDefault(Function(r) r.BodyCount = size),
                .Before = before.FirstOrDefault(Function(r) r.BodyCount = size)}
            For k = 0 To Math.Min(nowRounds.Count, beforeRounds.Count) - 1
                Dim pair As New BaselineRow With {
                    .Now = nowRounds(k).FirstOrDefault(Function(r) r.BodyCount = size),
                    .Before = beforeRounds(k).FirstOrDefault(Function(r) r.BodyCount = size)}
                If Not Double.IsNaN(pair.Ratio) Then row.PairRatios.Add(pair.Ratio)
            Next
            comparison.Rows.Add(row)
        Next
        Return comparison
    End Function

    ''' <summary>The sizes of <see cref="Sizes"/> that this run's gas sizes include.</summary>
    Public Shared Function SizesIn(gasSizes As IEnumerable(Of Integer)) As List(Of Integer)
        If gasSizes Is Nothing Then Throw New ArgumentNullException(NameOf(gasSizes))
        Return Sizes.Where(Function(n) gasSizes.Contains(n)).ToList()
    End Function

    ''' <summary>A ratio as the report prints it: "1.07×", or "—" when there is none.</summary>
    Public Shared Function RatioText(ratio As Double) As String
        Return If(Double.IsNaN(ratio), "—", ratio.ToString("0.00", CultureInfo.InvariantCulture) & "×")
    End Function
End Class
