Option Strict On

''' <summary>How far bodies have sunk into each other or into the walls: zero for a correct solver.</summary>
Friend Module Overlap
    ''' <summary>The deepest overlap between two circles or a circle and a wall, m (0 when none).</summary>
    Public Function Deepest(world As World) As Double
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim worst = 0.0
        Dim cs = world.Circles
        For i = 0 To cs.Count - 1
            Dim a = cs(i)
            If world.Walls Then
                worst = Math.Max(worst, a.Radius - a.Position.X)
                worst = Math.Max(worst, a.Radius - a.Position.Y)
                worst = Math.Max(worst, a.Position.X + a.Radius - world.Width)
                worst = Math.Max(worst, a.Position.Y + a.Radius - world.Height)
            End If
            For j = i + 1 To cs.Count - 1
                Dim b = cs(j)
                worst = Math.Max(worst, a.Radius + b.Radius - (a.Position - b.Position).Length)
            Next
        Next
        Return worst
    End Function
End Module
