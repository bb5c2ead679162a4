Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' The energy an inelastic collision takes (e &lt; 1), counted in <see cref="World.Dissipated"/>: the kinetic energy
''' of the bodies it struck, before the blow less after it and the rest rules that follow it at the same instant
''' (a bounce too small to follow ends in rest, and what it had left is taken too). The solver calls this only
''' when e &lt; 1, so the elastic gas does no bookkeeping at all. Apart from the collision code, which runs at
''' every collision. A cluster resolved at once (<see cref="ClusterResponse"/>) keeps fuller books, at any e
''' (a wedged body stopped loses energy even at e = 1): every body's energy, kinetic and potential, before and after.
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

    ''' <summary>
    ''' Each body's mechanical energy at the clock, ½ m v² + m g y (J; 0 for the dragged body), into
    ''' <paramref name="into"/> (grown to the number of bodies), and <see cref="World.Dissipated"/> as it is now:
    ''' the books before a step that may change any body's motion, closed by <see cref="NoteChange"/>.
    ''' </summary>
    Friend Function OpenBooks(s As SolverState, ByRef into As Double()) As Double
        Dim count = s.Bodies.Count
        If into.Length < count Then into = New Double(count - 1) {}
        For i = 0 To count - 1
            into(i) = Mechanical(s, i)
        Next
        Return s.World.Dissipated
    End Function

    ''' <summary>
    ''' Closes the books opened by <see cref="OpenBooks"/>: the mechanical energy the bodies have lost since, less what
    ''' was counted as dissipated meanwhile (a body set down on its support counts its own drop), is counted now.
    ''' A gain (which a cluster never makes with e ≤ 1, but for rounding) is not counted.
    ''' </summary>
    Friend Sub NoteChange(s As SolverState, before As Double(), dissipatedBefore As Double)
        Dim lost = 0.0
        For i = 0 To s.Bodies.Count - 1
            lost += before(i) - Mechanical(s, i)
        Next
        lost -= s.World.Dissipated - dissipatedBefore
        s.World.Dissipate(lost)
    End Sub

    ''' <summary>½ m v² + m g y of body i at the clock, J (0 for the dragged body).</summary>
    Private Function Mechanical(s As SolverState, i As Integer) As Double
        Dim body = s.Bodies.Shapes(i)
        If body Is s.World.DraggedBody OrElse s.Bodies.Info(i).InverseMass = 0 Then Return 0
        Dim m = s.Bodies.Motion(i)
        Dim x = m.Px, y = m.Py, vx = m.Vx, vy = m.Vy
        ' A body sliding round a corner has no parabola to read: its motion holds where and how fast it last was.
        If Not Double.IsNaN(m.Ay) Then m.StateAt(s.Now, x, y, vx, vy)
        Return body.Mass * (0.5 * (vx * vx + vy * vy) + s.G * y)
    End Function

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
