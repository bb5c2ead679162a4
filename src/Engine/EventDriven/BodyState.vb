Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' The motion of one movable circle as the event-driven solver predicts with it: at time T0 (s) it is
''' at (Px, Py) m with velocity (Vx, Vy) m/s and vertical acceleration Ay m/s²; at time t it is at
''' p + v (t − T0) + ½ a (t − T0)². Packed together (64 bytes) because every pair check reads all of
''' them for the partner: one cache line instead of one per array.
''' </summary>
Friend Structure BodyState
    Friend T0 As Double
    Friend Px As Double
    Friend Py As Double
    Friend Vx As Double
    Friend Vy As Double
    Friend Ay As Double
    ''' <summary>Radius, m.</summary>
    Friend R As Double
    Friend Mode As BodyMode

    ''' <summary>Position (m) and velocity (m/s) at time t (s), exactly on the parabola.</summary>
    <MethodImpl(MethodImplOptions.AggressiveInlining)>
    Friend Sub StateAt(t As Double, ByRef x As Double, ByRef y As Double, ByRef vx As Double, ByRef vy As Double)
        Dim tau = t - T0
        x = Px + Me.Vx * tau
        y = Py + (Me.Vy + 0.5 * Ay * tau) * tau
        vx = Me.Vx
        vy = Me.Vy + Ay * tau
    End Sub
End Structure
