Option Strict On

''' <summary>
''' The body whose next event the <see cref="Predictor"/> is looking for, as every scan sees it: where
''' it is and how it moves at the solver's clock, and the earliest event found so far. One value passed
''' by reference from scan to scan, in place of the dozen numbers each scan would otherwise take.
''' </summary>
Friend Structure Probe
    ''' <summary>The body's index in the body table.</summary>
    Friend Body As Integer
    ''' <summary>Whether it is asleep (two sleepers never meet, and a sleeper never leaves its cell).</summary>
    Friend Asleep As Boolean
    ''' <summary>Position at the clock, m.</summary>
    Friend Px, Py As Double
    ''' <summary>Velocity at the clock, m/s.</summary>
    Friend Vx, Vy As Double
    ''' <summary>Acceleration, m/s² (vertical gravity, or along the slope it slides on).</summary>
    Friend Ax, Ay As Double
    ''' <summary>A circle's radius, m; 0 for any other outline.</summary>
    Friend R As Double
    ''' <summary>The touching tolerance where it is, m (<see cref="SolverState.SlopAt"/>).</summary>
    Friend Slop As Double
    ''' <summary>When it next leaves its grid cell, s from now (∞ if never).</summary>
    Friend ExitTime As Double
    ''' <summary>The earliest event found so far, s from now (∞ while none).</summary>
    Friend Best As Double
    ''' <summary>What that event is.</summary>
    Friend Kind As EventKind
    ''' <summary>The body or obstacle it meets (−1 for a wall or none).</summary>
    Friend Other As Integer
    ''' <summary>Which part of it: the wall's side, the obstacle's feature, or which end of a face.</summary>
    Friend Feature As Integer

    ''' <summary>Records an event at <paramref name="dt"/> s from now when it comes before the best so far.</summary>
    Friend Sub Offer(dt As Double, what As EventKind, partner As Integer, part As Integer)
        If dt < Best Then
            Best = dt
            Kind = what
            Other = partner
            Feature = part
        End If
    End Sub

    ''' <summary>Records a meeting with body <paramref name="partner"/> at <paramref name="dt"/> s from now when it comes before the best so far.</summary>
    Friend Sub OfferBody(dt As Double, partner As Integer)
        If dt < Best Then
            Best = dt
            Kind = EventKind.Body
            Other = partner
        End If
    End Sub
End Structure
