Option Strict On

''' <summary>
''' A distance (or any gap) that changes smoothly with time, for <see cref="ConservativeAdvancement"/>:
''' positive while apart. An interface rather than a delegate so that a caller's motion object can
''' answer directly, with no closure made per query.
''' </summary>
Public Interface IDistanceFunction
    ''' <summary>d(t), m.</summary>
    Function Distance(time As Double) As Double

    ''' <summary>d'(t), m/s, or NaN when it is not known (only the first-order bound is then used).</summary>
    Function Rate(time As Double) As Double
End Interface
