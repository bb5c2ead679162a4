Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>
    ''' Every movable body's position and velocity and the world's time, taken before an advance, so that a
    ''' refused advance can be shown to have put the world back exactly as it was (to the bit).
    ''' </summary>
    Friend NotInheritable Class WorldSnapshot
        Private ReadOnly _bodies As Shape()
        Private ReadOnly _positions As Vector()
        Private ReadOnly _velocities As Vector()

        ''' <summary>Takes the world's state now.</summary>
        Friend Sub New(world As World)
            If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
            _bodies = world.Movables.ToArray()
            _positions = _bodies.Select(Function(b) b.Position).ToArray()
            _velocities = _bodies.Select(Function(b) b.Velocity).ToArray()
            Time = world.Time
        End Sub

        ''' <summary>The world's time when the snapshot was taken, s.</summary>
        Friend ReadOnly Property Time As Double

        ''' <summary>Nothing when the world is as it was, else the first thing that differs.</summary>
        Friend Function FirstDifference(world As World) As String
            If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
            Dim inv = CultureInfo.InvariantCulture
            If world.Time <> Time Then Return "the time is " & world.Time.ToString("R", inv) & " s, not " & Time.ToString("R", inv) & " s"
            If world.Movables.Count <> _bodies.Length Then Return "it has " & world.Movables.Count.ToString(inv) & " movable bodies, not " & _bodies.Length.ToString(inv)
            For i = 0 To _bodies.Length - 1
                Dim b = _bodies(i)
                If Not world.Movables(i) Is b Then Return "body " & b.Id & " is no longer where it was in the list"
                If Not FinalState.Same(b.Position, _positions(i)) Then Return b.Id & " is at " & b.Position.ToString() & ", not " & _positions(i).ToString()
                If Not FinalState.Same(b.Velocity, _velocities(i)) Then Return b.Id & " moves at " & b.Velocity.ToString() & ", not " & _velocities(i).ToString()
            Next
            Return Nothing
        End Function
    End Class
End Namespace
