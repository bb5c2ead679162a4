Option Strict On

''' <summary>
''' How a stepping solver moves the dragged body: its reference point travels in a straight line at
''' constant speed, reaching <see cref="World.DragTarget"/> exactly at the end of the advance. Moving it
''' gradually (rather than jumping there in the first sub-step) lets it push what is in the way instead
''' of teleporting through it.
''' </summary>
Friend Module DragStep
    ''' <summary>Moves the dragged body through one sub-step of <paramref name="h"/> s, with <paramref name="remaining"/> s (≥ h) left in the advance.</summary>
    Friend Sub Move(world As World, body As Shape, h As Double, remaining As Double)
        Dim target = world.DragTarget
        If remaining <= h OrElse remaining <= 0 Then
            body.Velocity = If(h > 0, (target - body.Position) / h, Vector.Zero)
            body.Position = target
            Return
        End If
        Dim v = (target - body.Position) / remaining
        body.Velocity = v
        body.Position += v * h
    End Sub
End Module
