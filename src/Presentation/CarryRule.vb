Option Strict On

''' <summary>
''' How far a carried body goes towards the cursor. It never enters a body it collides with and
''' never jumps over one, however fast the cursor moves: the move is swept (contact times solved
''' for) and it slides along what stops it. While time runs it also keeps clear of where each ball
''' could get to before the next frame (and a hair more, so it never arrives at a ball still moving):
''' a ball meets the carried one only when the carried one is not closing in on it, and bounces off
''' it as off a wall. The carried ball acts as if infinitely heavy: closing in on a ball caught
''' against a wall or another body would pump energy into it without limit (thousands of bounces a
''' second, and in the end the ball squeezed through), so it is never done.
''' </summary>
Public Module CarryRule
    ''' <summary>The gap kept from every ball while time runs, m: far below anything drawn or measured.</summary>
    Private Const Gap As Double = 0.000001

    ''' <summary>The offset (m) the carried <paramref name="body"/> reaches towards <paramref name="displacement"/>.</summary>
    ''' <param name="frameSeconds">simulated time until the carried body gets there (0 while paused: nothing else moves)</param>
    Public Function Reach(world As World, body As Shape, displacement As Vector, frameSeconds As Double) As Vector
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If Not (frameSeconds > 0) Then Return Placement.SlideTo(world, body, displacement)
        Dim g = world.Gravity
        ' The farthest a moving body can go in the frame: its speed for the frame, and what gravity adds.
        Dim clearance As Func(Of Shape, Double) =
            Function(b)
                If b.IsFixed Then Return 0.0
                Return Gap + b.Velocity.Length * frameSeconds + 0.5 * g * frameSeconds * frameSeconds
            End Function
        Return Placement.SlideTo(world, body, displacement, clearance:=clearance)
    End Function
End Module
