Option Strict On

''' <summary>
''' Archimedes' principle in a 2D world: a body in a liquid of (areal) density ρ_l is pushed up by the
''' weight of the liquid it displaces, ρ_l g A_sub (N), A_sub the area of the body inside the liquid
''' (<see cref="SubmergedArea"/>). The push is the work done against the liquid's pressure, so it has a
''' potential energy: moving the body up by dy lets the liquid back in, and U changes by −ρ_l g A_sub dy.
''' docs/forces.md, "Buoyancy".
''' </summary>
Public Module Buoyancy
    ''' <summary>The upward push, N: ρ_l g A_sub.</summary>
    Public Function Force(liquidDensity As Double, gravity As Double, part As Submerged) As Double
        Return liquidDensity * gravity * part.Area
    End Function

    ''' <summary>
    ''' The potential energy of the push, J: ρ_l g ∫ (s − y) dA over the part inside, s the surface's height.
    ''' It is the work of lifting the displaced liquid from where the body is up to the surface; its
    ''' derivative with respect to the body's height is −ρ_l g A_sub (each bit of area dA leaving the liquid
    ''' at the surface, where s − y = 0, changes nothing, so only the body's own rise counts).
    ''' </summary>
    Public Function Potential(liquidDensity As Double, gravity As Double, surface As Double, part As Submerged) As Double
        Return liquidDensity * gravity * (surface * part.Area - part.MomentY)
    End Function

    ''' <summary>The depth (m) a box of mass m (kg) and width w (m) floats at in a liquid of density ρ_l (kg/m²): m/(ρ_l w), where ρ_l g w d = m g.</summary>
    Public Function FloatingDepth(mass As Double, width As Double, liquidDensity As Double) As Double
        Return mass / (liquidDensity * width)
    End Function

    ''' <summary>
    ''' The period (s) of a box bobbing undamped about its floating depth: pushed down by y, it is pushed
    ''' back up by ρ_l g w y, so m ÿ = −ρ_l g w y, simple harmonic motion with T = 2π √(m/(ρ_l g w)).
    ''' </summary>
    Public Function BobbingPeriod(mass As Double, width As Double, liquidDensity As Double, gravity As Double) As Double
        Return 2 * Math.PI * Math.Sqrt(mass / (liquidDensity * gravity * width))
    End Function
End Module
