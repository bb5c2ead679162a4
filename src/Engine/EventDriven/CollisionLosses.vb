Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' The energy an inelastic collision takes (e &lt; 1), counted in <see cref="World.Dissipated"/>: the kinetic energy
''' of the bodies it struck, before the blow less after it and the rest rules that follow it at the same instant
''' (a bounce too small to follow ends in rest, and what it had left is taken too). The solver calls this only
''' when e &lt; 1, so the elastic gas does no bookkeeping at all. Apart from the collision code, which runs at
''' every collision.
''' </summary>
Friend Module CollisionLosses
    ''' <summary>Body i hit something immovable at the clock; its velocity was <paramref name="before"/> (m/s).</summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Friend Sub Note(s As SolverState, i As Integer, before As Vector)
        s.World.Dissipate(Kinetic(s, i, before) - Kinetic(s, i, VelocityNow(s, i)))
    End Sub

    ''' <summary>Bodies i and j collided at the clock; their velocities were <paramref name="beforeI"/> and <paramref name="beforeJ"/> (m/s).</summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Friend Sub Note(s As SolverState, i As Integer, beforeI As Vector, j As Integer, beforeJ As Vector)
        s.World.Dissipate(Kinetic(s, i, beforeI) + Kinetic(s, j, beforeJ) - Kinetic(s, i, VelocityNow(s, i)) - Kinetic(s, j, VelocityNow(s, j)))
    End Sub

    ''' <summary>½ m v² of body i (its own mass, whatever the rest rules make it count as in a blow), J; 0 for the dragged body.</summary>
    Private Function Kinetic(s As SolverState, i As Integer, v As Vector) As Double
        Dim body = s.Bodies.Shapes(i)
        If body Is s.World.DraggedBody Then Return 0
        Return 0.5 * body.Mass * v.LengthSquared
    End Function

    ''' <summary>Body i's velocity at the clock, m/s, as its motion now gives it.</summary>
    Private Function VelocityNow(s As SolverState, i As Integer) As Vector
        Dim m = s.Bodies.Motion(i)
        If m.T0 = s.Now OrElse Double.IsNaN(m.Ay) Then Return New Vector(m.Vx, m.Vy)
        Dim x, y, vx, vy As Double
        m.StateAt(s.Now, x, y, vx, vy)
        Return New Vector(vx, vy)
    End Function
End Module
