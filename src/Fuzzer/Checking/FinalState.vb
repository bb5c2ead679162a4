Option Strict On

Namespace Checking
    ''' <summary>Where every movable circle is and how fast it moves at the end of a run, for comparing two runs to the bit.</summary>
    Friend NotInheritable Class FinalState
        Private ReadOnly _ids As New List(Of String)
        Private ReadOnly _positions As New List(Of Vector)
        Private ReadOnly _velocities As New List(Of Vector)

        ''' <summary>Reads the world's movable circles, in the world's order.</summary>
        Friend Sub New(world As World)
            If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
            For Each c In world.Circles
                If c.IsFixed Then Continue For
                _ids.Add(c.Id)
                _positions.Add(c.Position)
                _velocities.Add(c.Velocity)
            Next
        End Sub

        ''' <summary>Nothing when both states are the same to the bit; otherwise a line naming the first body that differs.</summary>
        Friend Shared Function FirstDifference(a As FinalState, b As FinalState, nameA As String, nameB As String) As String
            If a._ids.Count <> b._ids.Count Then Return "different bodies at the end"
            For i = 0 To a._ids.Count - 1
                If Not String.Equals(a._ids(i), b._ids(i), StringComparison.Ordinal) Then Return "different bodies at the end"
                If Not Same(a._positions(i), b._positions(i)) OrElse Not Same(a._velocities(i), b._velocities(i)) Then
                    Return a._ids(i) & " ends at " & a._positions(i).ToString() & " moving " & a._velocities(i).ToString() & " in " & nameA &
                        ", at " & b._positions(i).ToString() & " moving " & b._velocities(i).ToString() & " in " & nameB
                End If
            Next
            Return Nothing
        End Function

        ''' <summary>Whether two vectors are equal to the bit (the fuzzer's one rule for "the same").</summary>
        Friend Shared Function Same(a As Vector, b As Vector) As Boolean
            Return BitConverter.DoubleToInt64Bits(a.X) = BitConverter.DoubleToInt64Bits(b.X) AndAlso
                BitConverter.DoubleToInt64Bits(a.Y) = BitConverter.DoubleToInt64Bits(b.Y)
        End Function
    End Class
End Namespace
