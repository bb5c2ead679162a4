Option Strict On

''' <summary>
''' A scene that ends at rest (a pile settling): its timed runs stop when every body is at rest, and the
''' report gives the wall-clock time that took beside the cost per simulated second.
''' </summary>
Friend Interface ISettlingScene
    ''' <summary>
    ''' Advances <paramref name="world"/> (solver attached, time 0) until every body is at rest by the
    ''' scene's test, or to <see cref="IBenchScene.SimulatedSeconds"/>, or until the budget runs out.
    ''' Returns the simulated time (s) at which the pile was found at rest, or NaN when it was not.
    ''' </summary>
    Function RunToRest(world As World, budget As RunBudget) As Double
End Interface
