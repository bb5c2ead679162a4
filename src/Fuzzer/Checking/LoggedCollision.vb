Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>One collision as the collisions CSV gives it: time, the two bodies, the kind, and both velocities before and after.</summary>
    Friend Structure LoggedCollision
        Friend Sub New(r As CollisionRecord)
            Time = r.Time
            A = r.A.Id
            B = If(r.B IsNot Nothing, r.B.Id, Nothing)
            Wall = r.Wall
            Kind = r.Kind
            ABefore = r.AVelocityBefore
            AAfter = r.AVelocityAfter
            BBefore = r.BVelocityBefore
            BAfter = r.BVelocityAfter
        End Sub

        ''' <summary>s</summary>
        Friend ReadOnly Time As Double
        Friend ReadOnly A As String
        ''' <summary>The other body's id, or Nothing for a wall.</summary>
        Friend ReadOnly B As String
        Friend ReadOnly Wall As WallSide
        Friend ReadOnly Kind As CollisionKind
        ''' <summary>m/s</summary>
        Friend ReadOnly ABefore As Vector
        Friend ReadOnly AAfter As Vector
        Friend ReadOnly BBefore As Vector
        Friend ReadOnly BAfter As Vector

        ''' <summary>True when every field is the same, numbers to the bit.</summary>
        Friend Function SameAs(other As LoggedCollision) As Boolean
            Return Bits(Time) = Bits(other.Time) AndAlso String.Equals(A, other.A, StringComparison.Ordinal) AndAlso
                String.Equals(B, other.B, StringComparison.Ordinal) AndAlso (B IsNot Nothing OrElse Wall = other.Wall) AndAlso
                Kind = other.Kind AndAlso SameBits(ABefore, other.ABefore) AndAlso SameBits(AAfter, other.AAfter) AndAlso
                SameBits(BBefore, other.BBefore) AndAlso SameBits(BAfter, other.BAfter)
        End Function

        ''' <summary>Folds every field's bits into a 64-bit FNV-1a hash.</summary>
        Friend Function Hash(seed As ULong) As ULong
            Dim h = seed
            h = Mix(h, CULng(Bits(Time)))
            h = MixText(h, A)
            h = MixText(h, If(B, "wall:" & Wall.ToString()))
            h = Mix(h, CULng(Kind))
            For Each v In {ABefore, AAfter, BBefore, BAfter}
                h = Mix(h, CULng(Bits(v.X)))
                h = Mix(h, CULng(Bits(v.Y)))
            Next
            Return h
        End Function

        Public Overrides Function ToString() As String
            Dim inv = CultureInfo.InvariantCulture
            Return "t = " & Time.ToString("R", inv) & " s, " & A & " with " & If(B, "wall:" & Wall.ToString().ToLowerInvariant()) &
                ", " & A & " " & ABefore.ToString() & " -> " & AAfter.ToString() & If(B IsNot Nothing, ", " & B & " " & BBefore.ToString() & " -> " & BAfter.ToString(), "")
        End Function

        Private Shared Function Bits(x As Double) As Long
            Return BitConverter.DoubleToInt64Bits(x)
        End Function

        Private Shared Function SameBits(a As Vector, b As Vector) As Boolean
            Return Bits(a.X) = Bits(b.X) AndAlso Bits(a.Y) = Bits(b.Y)
        End Function

        Private Shared Function Mix(h As ULong, value As ULong) As ULong
            For i = 0 To 7
                h = (h Xor ((value >> (8 * i)) And &HFFUL)) * 1099511628211UL
            Next
            Return h
        End Function

        Private Shared Function MixText(h As ULong, text As String) As ULong
            For Each ch In text
                h = Mix(h, CULng(AscW(ch)))
            Next
            Return Mix(h, &HFFFFUL)
        End Function
    End Structure
End Namespace
