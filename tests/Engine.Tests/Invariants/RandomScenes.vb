Option Strict On
Imports PhysicsEngine

''' <summary>Seeded random scenes for the invariant tests: mixed circles, fixed circles and rectangles, walls on.</summary>
Public NotInheritable Class RandomScenes
    Private Sub New()
    End Sub

    ''' <summary>
    ''' A walled 4 m × 3 m box with g, e as given, two rectangles, two fixed circles and
    ''' <paramref name="count"/> movable circles (radius 0.03–0.15 m, mass 0.1–10 kg, speed components
    ''' within ±3 m/s), placed so that nothing starts overlapping. The same seed gives the same scene.
    ''' </summary>
    Public Shared Function Build(seed As Integer, count As Integer, gravity As Double, restitution As Double) As World
        Dim rng As New Random(seed)
        Dim w As New World(4.0, 3.0, gravity, restitution)
        w.Add(New Rectangle(New Vector(0.5 + rng.NextDouble(), 0.0), 0.4 + rng.NextDouble() * 0.6, 0.2 + rng.NextDouble() * 0.5))
        w.Add(New Rectangle(New Vector(2.2 + rng.NextDouble(), 1.0 + rng.NextDouble()), 0.3 + rng.NextDouble() * 0.5, 0.1 + rng.NextDouble() * 0.3))
        For i = 1 To 2
            TryPlace(w, rng, Function(p, r) Circle.CreateFixed(p, r), 0.05, 0.2)
        Next
        Dim placed = 0
        Do While placed < count
            If TryPlace(w, rng, Function(p, r) New Circle(p, r, 0.1 + rng.NextDouble() * 9.9,
                                                          New Vector(rng.NextDouble() * 6 - 3, rng.NextDouble() * 6 - 3)), 0.03, 0.15) Then
                placed += 1
            End If
        Loop
        Return w
    End Function

    Private Shared Function TryPlace(w As World, rng As Random, make As Func(Of Vector, Double, Circle), rMin As Double, rMax As Double) As Boolean
        Dim r = rMin + rng.NextDouble() * (rMax - rMin)
        Dim p = New Vector(r + rng.NextDouble() * (w.Width - 2 * r), r + rng.NextDouble() * (w.Height - 2 * r))
        For Each c In w.Circles
            If (c.Position - p).Length < c.Radius + r Then Return False
        Next
        For Each rect In w.Rectangles
            If Collider.CircleRectangle(p, r, rect.Min, rect.Max).Depth > -0.001 Then Return False
        Next
        w.Add(make(p, r))
        Return True
    End Function

    ''' <summary>Kinetic plus potential energy of the movable circles, J.</summary>
    Public Shared Function Energy(w As World) As Double
        Return w.KineticEnergy() + w.PotentialEnergy()
    End Function
End Class
