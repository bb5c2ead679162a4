Option Strict On

''' <summary>
''' The two-dimensional gas laws the pressure graph compares with. In 2D a "pressure" is a force per
''' unit length of wall (N/m) and a "volume" an area (m²): the ideal gas law is P A = N k T.
''' </summary>
Public NotInheritable Class GasLaw
    Private Sub New()
    End Sub

    ''' <summary>N k T / A, N/m: <paramref name="count"/> bodies at <paramref name="kT"/> (J) in <paramref name="area"/> (m²).</summary>
    Public Shared Function IdealPressure(count As Integer, kT As Double, area As Double) As Double
        If Not (area > 0) Then Return Double.NaN
        Return count * kT / area
    End Function

    ''' <summary>
    ''' How much harder hard discs press than an ideal gas at packing fraction
    ''' <paramref name="eta"/> (the discs' area over the container's): Henderson's equation of state,
    ''' Z = (1 + η²/8) / (1 − η)², good to a fraction of a percent for a fluid of equal discs.
    ''' </summary>
    Public Shared Function HardDiscFactor(eta As Double) As Double
        If Not (eta >= 0) OrElse eta >= 1 Then Return Double.NaN
        Return (1 + eta * eta / 8) / ((1 - eta) * (1 - eta))
    End Function

    ''' <summary>
    ''' kT of bodies that move in two dimensions without turning, J: each has two degrees of freedom,
    ''' so its mean kinetic energy is 2 × ½kT = kT (equipartition).
    ''' </summary>
    Public Shared Function Temperature(totalKinetic As Double, count As Integer) As Double
        If count <= 0 Then Return Double.NaN
        Return totalKinetic / count
    End Function
End Class
