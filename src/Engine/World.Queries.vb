Option Strict On

' Totals over the movable circles: what the app shows and what the tests check is conserved.
Partial Public NotInheritable Class World
    ''' <summary>Σ ½ m v² over movable circles, J.</summary>
    Public Function KineticEnergy() As Double
        Dim sum = 0.0
        For Each c In _circles
            sum += c.KineticEnergy
        Next
        Return sum
    End Function

    ''' <summary>Σ m g y over movable circles, J (zero level at y = 0, the container's floor).</summary>
    Public Function PotentialEnergy() As Double
        Dim sum = 0.0
        For Each c In _circles
            If Not c.IsFixed Then sum += c.Mass * _gravity * c.Position.Y
        Next
        Return sum
    End Function

    ''' <summary>Σ m v over movable circles, kg·m/s.</summary>
    Public Function Momentum() As Vector
        Dim px = 0.0, py = 0.0
        For Each c In _circles
            If Not c.IsFixed Then
                px += c.Mass * c.Velocity.X
                py += c.Mass * c.Velocity.Y
            End If
        Next
        Return New Vector(px, py)
    End Function
End Class
