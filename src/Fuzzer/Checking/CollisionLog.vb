Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>
    ''' Every collision of a run, in order: the first <see cref="Kept"/> in full (to name the first one that
    ''' differs between two runs), the rest folded into a hash, so a run of tens of millions of collisions
    ''' still compares, in bounded memory.
    ''' </summary>
    Friend NotInheritable Class CollisionLog
        Private Const HashStart As ULong = 14695981039346656037UL

        Private ReadOnly _kept As New List(Of LoggedCollision)
        Private ReadOnly _limit As Integer
        Private _tailHash As ULong = HashStart

        ''' <param name="limit">how many collisions to keep in full</param>
        Friend Sub New(Optional limit As Integer = 400_000)
            _limit = limit
        End Sub

        ''' <summary>Collisions logged, kept or hashed.</summary>
        Friend ReadOnly Property Count As Long

        ''' <summary>The collisions kept in full (the first ones).</summary>
        Friend ReadOnly Property Kept As IReadOnlyList(Of LoggedCollision)
            Get
                Return _kept
            End Get
        End Property

        ''' <summary>Logs one collision (the world's collision listener).</summary>
        Friend Sub Add(record As CollisionRecord)
            Add(New LoggedCollision(record))
        End Sub

        ''' <summary>Logs one collision.</summary>
        Friend Sub Add(entry As LoggedCollision)
            If _kept.Count < _limit Then
                _kept.Add(entry)
            Else
                _tailHash = entry.Hash(_tailHash)
            End If
            _Count += 1
        End Sub

        ''' <summary>
        ''' Nothing when both logs hold the same collisions, to the bit; otherwise a line naming the first
        ''' difference (and <paramref name="time"/> is when it happened, s).
        ''' </summary>
        Friend Shared Function FirstDifference(a As CollisionLog, b As CollisionLog, nameA As String, nameB As String, ByRef time As Double) As String
            Dim common = Math.Min(a._kept.Count, b._kept.Count)
            For i = 0 To common - 1
                If Not a._kept(i).SameAs(b._kept(i)) Then
                    time = Math.Min(a._kept(i).Time, b._kept(i).Time)
                    Return "collision " & Ordinal(i) & " differs: " & nameA & " " & a._kept(i).ToString() & "; " & nameB & " " & b._kept(i).ToString()
                End If
            Next
            If a._kept.Count <> b._kept.Count Then
                Dim longer = If(a._kept.Count > b._kept.Count, a, b)
                time = longer._kept(common).Time
                Return "collision " & Ordinal(common) & " is only in " & If(longer Is a, nameA, nameB) & ": " & longer._kept(common).ToString() &
                    " (" & a.Count.ToString(CultureInfo.InvariantCulture) & " against " & b.Count.ToString(CultureInfo.InvariantCulture) & " collisions)"
            End If
            If a.Count <> b.Count OrElse a._tailHash <> b._tailHash Then
                time = Double.NaN
                Return "the first " & common.ToString(CultureInfo.InvariantCulture) & " collisions agree, the later ones differ (" &
                    a.Count.ToString(CultureInfo.InvariantCulture) & " against " & b.Count.ToString(CultureInfo.InvariantCulture) & " collisions)"
            End If
            Return Nothing
        End Function

        Private Shared Function Ordinal(i As Integer) As String
            Return "#" & (i + 1).ToString(CultureInfo.InvariantCulture)
        End Function
    End Class
End Namespace
