Option Strict On

''' <summary>How a stepping solver moves the dragged circle: straight towards the target, reaching it at the end of the advance.</summary>
Friend Module DragStep
    ''' <summary>Moves the dragged circle by one sub-step of h seconds, at the speed that reaches the target on time.</summary>
    Friend Sub Move(world As World, c As Circle, h As Double)
        Dim toGo = world.DragTarget - c.Position
        c.Velocity = toGo / Math.Max(h, 1.0E-12)
        c.Position = world.DragTarget
    End Sub
End Module
