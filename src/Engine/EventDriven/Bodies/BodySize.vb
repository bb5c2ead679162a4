Option Strict On

''' <summary>
''' A movable body's sizes as the event-driven solver reads them: for the grid, for polygon pairs and
''' for the resting rules' thresholds, so not in every collision (which is why they are not in
''' <see cref="BodyInfo"/>).
''' </summary>
Friend Structure BodySize
    ''' <summary>How far the body reaches from its reference point, m (a circle's radius).</summary>
    Friend Reach As Double
    ''' <summary>The body's size for the resting rules' thresholds, m: a circle's radius, else the radius of a disc of the same area.</summary>
    Friend Scale As Double
End Structure
