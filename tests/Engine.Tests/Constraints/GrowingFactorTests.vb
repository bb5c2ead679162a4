Option Strict On

Imports Xunit

''' <summary>
''' <see cref="GrowingFactor"/> keeps exactly the rows that <see cref="ConstraintSet"/> would take one after another:
''' a row is refused where the full solve of the rows kept so far and that row refuses it.
''' </summary>
Public Class GrowingFactorTests
    <Theory>
    <InlineData(1)>
    <InlineData(2)>
    <InlineData(3)>
    <InlineData(4)>
    Public Sub KeepsTheRowsTheFullSolveTakes(seed As Integer)
        Dim random As New Random(seed)
        ' Four bodies of different masses; rods between them and to fixed points, some repeated (dependent on
        ' those before), so that both answers occur.
        Const bodies = 4
        Dim inverseMass = Enumerable.Range(0, bodies).Select(Function(k) 1 / (0.1 + 10 * random.NextDouble())).ToArray()
        Dim state(4 * bodies - 1) As Double
        For k = 0 To bodies - 1
            state(4 * k) = random.NextDouble()
            state(4 * k + 1) = random.NextDouble()
        Next
        Dim rows As New List(Of Constraint)
        For n = 1 To 14
            Dim a = random.Next(bodies)
            Dim b = random.Next(-1, bodies)
            If b = a Then b = -1
            Dim anchor = New Vector(random.NextDouble(), random.NextDouble())
            rows.Add(Constraint.Tie(a, b, anchor, 0.5, holds:=True))
            If random.NextDouble() < 0.3 Then rows.Add(Constraint.Tie(a, b, anchor, 0.5, holds:=True)) ' the same again
        Next

        Dim grown As New GrowingFactor(inverseMass, ConstraintSet.DefaultIndependence)
        Dim kept As New List(Of Constraint)
        Dim refused = 0
        For Each row In rows
            Dim u As Vector, value As Double, rate As Double, curvature As Double
            row.Measure(state, u, value, rate, curvature)
            Dim fullTakes As Boolean
            Dim accelerations(4 * bodies - 1) As Double
            Try
                Call New ConstraintSet(kept.Append(row).ToArray(), inverseMass).Tensions(state, accelerations)
                fullTakes = True
            Catch ex As InvalidOperationException
                fullTakes = False
            End Try
            Dim grownTakes = grown.TryAdd(row, u)
            Assert.Equal(fullTakes, grownTakes)
            If grownTakes Then kept.Add(row) Else refused += 1
        Next
        ' Four bodies move in 8 ways: at most 8 rows can be kept, and the repeats must be refused.
        Assert.True(kept.Count <= 2 * bodies)
        Assert.True(refused > 0)
    End Sub
End Class
