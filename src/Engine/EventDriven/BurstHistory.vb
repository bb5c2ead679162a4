Option Strict On

''' <summary>
''' One body's recent collisions, as the resting rules read them (<see cref="RestRules"/>): when it last
''' collided, its current burst, and its hits at one instant. Kept together, 32 bytes, because every
''' collision reads and writes all of them for both bodies: one cache line instead of one per array.
''' </summary>
Friend Structure HitHistory
    ''' <summary>Time of the body's last collision, s (for the inelastic-collapse guard).</summary>
    Friend LastHit As Double
    ''' <summary>Start of the body's current burst of collisions, s (for the sleeping rule).</summary>
    Friend BurstStart As Double
    ''' <summary>Instant of the body's last collision, s (jam detection).</summary>
    Friend SameTime As Double
    ''' <summary>Collisions in the current burst.</summary>
    Friend BurstCount As Integer
    ''' <summary>Collisions at <see cref="SameTime"/> after the first.</summary>
    Friend SameCount As Integer

    ''' <summary>No collisions yet.</summary>
    Friend Shared ReadOnly Property Fresh As New HitHistory() With {
        .LastHit = Double.NegativeInfinity, .BurstStart = Double.NegativeInfinity, .SameTime = Double.NaN}
End Structure
