Option Strict On

' Totals over the movable bodies: what the app shows and what the tests check is conserved.
Partial Public NotInheritable Class World
    ''' <summary>Σ ½ m v² over movable bodies, J.</summary>
    Public Function KineticEnergy() As Double
        Dim sum = 0.0
        For Each b In _movables
            sum += b.KineticEnergy
        Next
        Return sum
    End Function

    ''' <summary>
    ''' Σ m g y over movable bodies (y of each one's centre of mass; zero level at y = 0, the container's
    ''' floor) plus the energy stored in springs, Σ ½ k extension², plus buoyancy's in liquids
    ''' (<see cref="BuoyancyPotentialEnergy"/>), J.
    ''' </summary>
    Public Function PotentialEnergy() As Double
        Dim sum = 0.0
        For Each b In _movables
            sum += b.Mass * _gravity * b.CentreOfMass.Y
        Next
        For Each l In _links
            sum += l.StoredEnergy
        Next
        Return sum + BuoyancyPotentialEnergy()
    End Function

    ''' <summary>Σ m v over movable bodies, kg·m/s.</summary>
    Public Function Momentum() As Vector
        Dim px = 0.0, py = 0.0
        For Each b In _movables
            px += b.Mass * b.Velocity.X
            py += b.Mass * b.Velocity.Y
        Next
        Return New Vector(px, py)
    End Function

    ''' <summary>The centre of mass of the movable bodies, m (NaN when there are none).</summary>
    Public Function CentreOfMass() As Vector
        Dim m = 0.0, mx = 0.0, my = 0.0
        For Each b In _movables
            Dim c = b.CentreOfMass
            m += b.Mass
            mx += b.Mass * c.X
            my += b.Mass * c.Y
        Next
        Return New Vector(mx / m, my / m)
    End Function
End Class
