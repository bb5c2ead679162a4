Option Strict On
Imports System.Globalization

''' <summary>
''' Whether a stepping solver can follow a scene's springs at all. Semi-implicit Euler and Verlet move a mass
''' on a spring, x'' = −ω² x, stably only when ω h &lt; 2 (h the step, s): beyond that each step multiplies the
''' oscillation by a factor of modulus above 1 and it grows without bound, to infinity and NaN. For a spring
''' of stiffness k (N/m) between bodies of inverse masses w_A and w_B (1/kg; 0 for a fixed body or a point),
''' ω² = k (w_A + w_B) is the stiffness of the mode that stretches only that spring, and the fastest mode of the
''' whole scene is at least that fast (a Rayleigh quotient: other springs only add stiffness), so ω h ≥ 2 for
''' one spring is enough to make the method unstable on the scene.
''' </summary>
Public Module StepStability
    ''' <summary>ω h at and beyond which semi-implicit Euler and Verlet are unstable on a spring.</summary>
    Public Const Limit As Double = 2.0

    ''' <summary>
    ''' The spring with the largest ω h at the step <paramref name="stepSize"/> (s), and that ω h; (Nothing, 0) when the
    ''' world has no spring. It is beyond the method's limit when ω h ≥ <see cref="Limit"/>.
    ''' </summary>
    Public Function Stiffest(world As World, stepSize As Double) As (Spring As Link, OmegaH As Double)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim worst = 0.0
        Dim found As Link = Nothing
        For Each l In world.Links
            If l.Kind <> LinkKind.Spring Then Continue For
            Dim w = l.A.InverseMass + If(l.B Is Nothing, 0.0, l.B.InverseMass)
            Dim omegaH = Math.Sqrt(l.Stiffness * w) * stepSize
            If omegaH > worst Then
                worst = omegaH
                found = l
            End If
        Next
        Return (found, worst)
    End Function

    ''' <summary>Nothing, or a line naming the spring with the largest ω h when that is at least <see cref="Limit"/>, with its figures.</summary>
    ''' <param name="stepSize">the solver's step h, s</param>
    Public Function BeyondLimit(world As World, stepSize As Double) As String
        Dim s = Stiffest(world, stepSize)
        If s.OmegaH < Limit Then Return Nothing
        Dim inv = CultureInfo.InvariantCulture
        Return "spring " & s.Spring.Id & " has ω h = " & s.OmegaH.ToString("G4", inv) & " (k = " & s.Spring.Stiffness.ToString("G4", inv) & " N/m, ω = " &
            (s.OmegaH / stepSize).ToString("G4", inv) & " rad/s, h = " & stepSize.ToString("R", inv) & " s), beyond the stability limit ω h < 2 of an explicit step"
    End Function
End Module
