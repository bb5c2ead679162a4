Option Strict On

''' <summary>
''' The maths of one pair of body kinds: when they touch, and the contact normal when they do. A
''' feature numbers what was touched in the pair's Minkowski difference K = B ⊕ (−A) (see
''' <see cref="Outline.MinkowskiDifference"/>): an edge 0 … E − 1 of K (a face), or E + k for its
''' rounded corner k. Every rule numbers features this way, so what follows a contact (sliding along a
''' face, rounding a corner) works the same whichever rule found it.
''' </summary>
Friend Interface IContactRule
    ''' <summary>When A first touches B while closing (s from now), +∞ if never before the query's horizon; which feature.</summary>
    Function TimeOfImpact(ByRef q As ContactQuery, ByRef feature As Integer) As Double

    ''' <summary>
    ''' The unit normal from B towards A when they touch with A at q.D (at the event), touching the
    ''' given feature; and, in <paramref name="correction"/>, how far A must move along it (m, ≥ 0) to
    ''' stand exactly on a face rounding left it a hair inside (0 for a corner).
    ''' </summary>
    Function Normal(ByRef q As ContactQuery, feature As Integer, ByRef correction As Double) As Vector
End Interface
