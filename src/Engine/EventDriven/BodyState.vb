Option Strict On

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
End Structure
