Option Strict On
Imports System.Globalization

''' <summary>
''' Whether the bodies a run ends with at rest are held where they rest. For each movable body standing exactly still
''' (asleep), its free-body diagram (<see cref="BodyForces.Diagram"/>: weight, and the frictionless contact forces
''' found for it and everything touching it) gives its acceleration: 0 at a true rest, not 0 where the forces would
''' move it (a ball in the V of two balls that nothing holds apart on a frictionless floor). Asked of the event solver,
''' which puts bodies to sleep; a stepping solver's bodies are still only by chance, now and then, on their way.
''' </summary>
Friend Module RestBalance
    ''' <summary>An acceleration (m/s²) below this counts as none: rounding in the forces found.</summary>
    Friend Const Tolerance As Double = 0.000001

    ''' <summary>Counts the still bodies (<paramref name="still"/>) and returns how many of them are not held; <paramref name="largest"/> is the largest acceleration among them (m/s²).</summary>
    Friend Function Unbalanced(world As World, ByRef still As Integer, ByRef largest As Double) As Integer
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        still = 0
        largest = 0
        Dim count = 0
        For Each body In world.Movables
            If body.Velocity <> Vector.Zero Then Continue For
            still += 1
            Dim a = BodyForces.Diagram(world, body).Acceleration.Length
            If a > Tolerance Then
                count += 1
                largest = Math.Max(largest, a)
            End If
        Next
        Return count
    End Function

    ''' <summary>
    ''' A clause for a scene's note: "; all 40 still bodies held" or "; 38 of 40 still bodies not held (forces give up to
    ''' 9.9 m/s²)"; empty when no body is still, or the world's solver is not the event solver.
    ''' </summary>
    Friend Function Note(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If TypeOf world.Solver IsNot EventDrivenSolver Then Return ""
        Dim still As Integer, largest As Double
        Dim count = Unbalanced(world, still, largest)
        If still = 0 Then Return ""
        Dim stillText = still.ToString(CultureInfo.InvariantCulture)
        If count = 0 Then Return "; all " & stillText & " still bodies held"
        Return "; " & count.ToString(CultureInfo.InvariantCulture) & " of " & stillText & " still bodies not held (forces give up to " &
               largest.ToString("0.0##", CultureInfo.InvariantCulture) & " m/s²)"
    End Function
End Module
