Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' How one movable body moves between events, as every prediction reads it: at time T0 (s) its
''' reference point is at (Px, Py) m with velocity (Vx, Vy) m/s and constant acceleration (Ax, Ay)
''' m/s², so at time t it is at p + v (t − T0) + ½ a (t − T0)². A free body has a = (0, −g); a body
''' held on a level support or asleep has a = 0; a body sliding down a slope has the slope's share
''' of gravity. Ay is NaN while the body's path is not a parabola (sliding round a corner), so no
''' prediction mistakes it for one. Packed together (64 bytes) because every pair check reads all of
''' it for the partner: one cache line instead of one per array.
''' </summary>
Friend Structure Motion
    Friend T0 As Double
    Friend Px As Double
    Friend Py As Double
    Friend Vx As Double
    Friend Vy As Double
    Friend Ay As Double
    ''' <summary>Rounding radius, m: a circle's radius (0 for a polygon).</summary>
    Friend R As Double
    Friend Ax As Double

    ''' <summary>Position (m) and velocity (m/s) at time t (s), exactly on the parabola.</summary>
    <MethodImpl(MethodImplOptions.AggressiveInlining)>
    Friend Sub StateAt(t As Double, ByRef x As Double, ByRef y As Double, ByRef vx As Double, ByRef vy As Double)
        Dim tau = t - T0
        x = Px + (Me.Vx + 0.5 * Ax * tau) * tau
        y = Py + (Me.Vy + 0.5 * Ay * tau) * tau
        vx = Me.Vx + Ax * tau
        vy = Me.Vy + Ay * tau
    End Sub

    ''' <summary>Moves the reference time to t (s) along the path: same motion, new starting point.</summary>
    Friend Sub MoveTo(t As Double)
        If t = T0 Then Return
        ' Through locals: passing its own fields by reference would keep the whole structure in memory.
        Dim x, y, vx, vy As Double
        StateAt(t, x, y, vx, vy)
        Px = x
        Py = y
        Me.Vx = vx
        Me.Vy = vy
        T0 = t
    End Sub
End Structure
