Option Strict On

''' <summary>
''' Seeing momentum: the centre of mass and its velocity, the total momentum Σp, the momenta
''' diagram, the impulses Δp at collisions and fading path traces, each switched on and off.
''' </summary>
Friend NotInheritable Class MomentumViews
    Private ReadOnly _stage As Stage
    Private ReadOnly _room As Func(Of Double)

    ''' <param name="room">the longest a momentum arrow may be drawn now, px (it follows the canvas's size)</param>
    Public Sub New(stage As Stage, room As Func(Of Double))
        _stage = stage
        _room = room
    End Sub

    ''' <summary>The tutorial's page on the momentum views, the walls toggle and typing into the tables.</summary>
    Public Shared ReadOnly Property MomentumHelp As New HelpTopic("8. Seeing momentum, walls, typing values",
        "Under the view options, six boxes: """ & MomentumCaptions.CentreOfMass & """ marks the centre of mass of the moving bodies (a quartered disc, CM) with its velocity arrow. """ &
        MomentumCaptions.TotalMomentum & """ draws their total momentum Σp from it. """ & MomentumCaptions.MomentaDiagram & """ shows, in the top-right corner, each body's momentum tip to tail in its colour, and the sum Σp in purple: in a collision between balls the chain changes but the sum does not. """ &
        MomentumCaptions.Impulses & """ shows, for a second, the impulse Δp each body receives at a collision, from the point of contact: two balls get equal and opposite arrows; a ball at a wall gets one. """ &
        MomentumCaptions.Traces & """ leaves a fading line behind each body (the last 3 s; in a crowded scene, the first 16 bodies). The key in the corner gives the scale of every momentum arrow." & vbLf & "" & vbLf &
        """" & MomentumCaptions.Walls & """ off takes the sides of the box away: it is drawn as an orange dashed outline, and balls fly out through it. On again, balls outside are brought back in. Restart goes back to the scene's own choice." & vbLf & "" & vbLf &
        "To set a value exactly, double-click its cell in a table (or select a row and press F2): x, y, vx, vy, mass and the size (a ball's radius, or a box's or polygon's width × height, typed as 0.8 × 0.5). Type the value and press Enter; Esc cancels. It is checked as the Add panel checks its boxes, and a position inside another body or outside the box is refused. Restart comes back to what you typed.")

    ''' <summary>The maths page on the momentum views.</summary>
    Public Shared ReadOnly Property MomentumMaths As New HelpTopic("Centre of mass, total momentum and impulse",
        "Only moving bodies count (a fixed body never moves and has no momentum). With masses mᵢ at centres rᵢ moving at vᵢ:" & vbLf & "" & vbLf &
        "  M = Σ mᵢ (kg)" & vbLf & "  centre of mass R = Σ mᵢ rᵢ / M (m)" & vbLf & "  total momentum P = Σ mᵢ vᵢ (kg·m/s)" & vbLf & "  velocity of the centre of mass V = P / M (m/s)" & vbLf & "" & vbLf &
        "With no outside force (no gravity, no walls) P never changes, so the centre of mass moves in a straight line at V whatever the bodies do." & vbLf & "" & vbLf &
        "At a collision each body receives an impulse Δp = m (v after − v before) (N·s = kg·m/s). Between two balls the impulses are equal and opposite (Newton's third law), so P is conserved. At a wall the ball's Δp is the wall's impulse on it: at e = 1 a ball hitting a wall square on at speed v gets 2 m v back.")

    ''' <summary>Whether the centre of mass of the movable bodies is marked, with its velocity arrow.</summary>
    Public ReadOnly Property ShowCentreOfMass As Boolean

    ''' <summary>Whether the total momentum Σp is drawn as an arrow from the centre of mass.</summary>
    Public ReadOnly Property ShowTotalMomentum As Boolean

    ''' <summary>Whether the momenta diagram (each body's p tip to tail, and Σp) is drawn in a corner of the canvas.</summary>
    Public ReadOnly Property ShowMomentaDiagram As Boolean

    ''' <summary>Whether each collision's impulses Δp are drawn for a moment at the contact.</summary>
    Public ReadOnly Property ShowImpulses As Boolean

    ''' <summary>Whether bodies leave fading traces of where they have been.</summary>
    Public ReadOnly Property ShowTraces As Boolean

    ''' <summary>The impulses on show (recorded only while <see cref="ShowImpulses"/> is on).</summary>
    Public ReadOnly Property Impulses As New ImpulseMarks()

    ''' <summary>The path traces (sampled only while <see cref="ShowTraces"/> is on).</summary>
    Public ReadOnly Property Traces As New PathTraces()

    ''' <summary>The momentum arrows' scale (Σp, the diagram and the impulses share it).</summary>
    Public ReadOnly Property MomentumArrows As New MomentumScale()

    ''' <summary>The centre of mass, total mass and total momentum of the movable bodies now.</summary>
    Public ReadOnly Property Momentum As MomentumSummary
        Get
            Return MomentumSummary.Measure(_stage.World)
        End Get
    End Property

    ''' <summary>The momenta diagram of the movable bodies now.</summary>
    Public Function Momenta() As MomentaDiagram
        Return New MomentaDiagram(_stage.World)
    End Function

    ''' <summary>Whether any momentum view needs the momentum scale (and its key) drawn.</summary>
    Public ReadOnly Property ShowsMomentumArrows As Boolean
        Get
            Return ShowTotalMomentum OrElse ShowMomentaDiagram OrElse ShowImpulses
        End Get
    End Property

    ''' <summary>The centre-of-mass marker and its velocity arrow on or off.</summary>
    Public Sub SetShowCentreOfMass(value As Boolean)
        _ShowCentreOfMass = value
        _stage.Emit("centre of mass " & If(value, "on", "off"))
        EmitMomentumViews()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>The total-momentum arrow on or off.</summary>
    Public Sub SetShowTotalMomentum(value As Boolean)
        _ShowTotalMomentum = value
        _stage.Emit("total momentum " & If(value, "on", "off"))
        EmitMomentumViews()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>The momenta diagram on or off.</summary>
    Public Sub SetShowMomentaDiagram(value As Boolean)
        _ShowMomentaDiagram = value
        _stage.Emit("momenta diagram " & If(value, "on", "off"))
        EmitMomentumViews()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>The impulse arrows on or off (turning them off forgets those on show).</summary>
    Public Sub SetShowImpulses(value As Boolean)
        _ShowImpulses = value
        If Not value Then Impulses.Clear()
        _stage.Emit("impulses " & If(value, "on", "off"))
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>Path traces on or off (turning them off forgets them; on again starts afresh).</summary>
    Public Sub SetShowTraces(value As Boolean)
        _ShowTraces = value
        Traces.Clear()
        If value Then Traces.Sample(_stage.World)
        _stage.Emit("traces " & If(value, "on", "off"))
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>Once per frame (from the presenter's Tick): traces and impulse marks follow the world.</summary>
    Public Sub FollowMomentumViews(realSeconds As Double, ran As Boolean)
        If ShowTraces AndAlso ran Then Traces.Follow(_stage.World, realSeconds)
        If ShowImpulses Then
            EmitNewImpulses()
            ' Paused, a mark stays: the teacher can stop time to look at it.
            If ran Then Impulses.Age(realSeconds)
        End If
        If ShowsMomentumArrows Then
            ' Room for the longest momentum arrow: the diagram's corner, a fifth of the canvas's smaller side.
            Dim diagram = Momenta()
            Dim longest = diagram.Extent
            For Each m In Impulses.Marks
                longest = Math.Max(longest, m.Impulse.Length)
            Next
            MomentumArrows.Update(longest, _room())
        End If
    End Sub

    ''' <summary>A collision from the engine: its impulses are noted while they are shown.</summary>
    Public Sub NoteImpulses(record As CollisionRecord)
        If ShowImpulses Then Impulses.Record(record)
    End Sub

    ''' <summary>A new scene, a restart or a reset: the traces and impulses of the old one go.</summary>
    Public Sub ForgetMomentumViews()
        Traces.Clear()
        Impulses.Clear()
    End Sub

    ''' <summary>Places the marks of this frame's collisions and, with a trace, lists the first few (GUI tests check them against the bodies).</summary>
    Private Sub EmitNewImpulses()
        Dim fresh = If(Not _stage.Tracing, 0, Impulses.Marks.Where(Function(m) Not m.IsLocated).Count())
        Impulses.Locate(_stage.World)
        If fresh = 0 Then Return
        Dim marks = Impulses.Marks
        For i = marks.Count - fresh To Math.Min(marks.Count, marks.Count - fresh + 8) - 1
            Dim m = marks(i)
            _stage.Emit("impulse " & m.Body.Id & " Δp " & Units.Pair(m.Impulse, 4) & " kg·m/s at " & Units.Pair(m.At, 3) & " m against " &
                 If(m.Other IsNot Nothing, m.Other.Id, "wall:" & m.Wall.ToString().ToLowerInvariant()) & " t=" & Units.Num(m.Time, 4))
        Next
    End Sub

    ''' <summary>With a trace: the centre of mass, its velocity and Σp as the views show them (GUI tests compare these with the bodies).</summary>
    Public Sub EmitMomentumViews()
        If Not _stage.Tracing Then Return
        Dim s = Momentum
        If Not s.HasBodies Then
            _stage.Emit("momentum views: no movable bodies")
            Return
        End If
        _stage.Emit("centre of mass at " & Units.Pair(s.CentreOfMass, 4) & " m v " & Units.Pair(s.Velocity, 4) & " m/s total mass " & Units.Num(s.Mass, 4) &
             " kg Σp " & Units.Pair(s.Momentum, 4) & " kg·m/s")
        If ShowTraces Then
            For Each b In Traces.Bodies.Take(8)
                Dim pts = Traces.Points(b)
                If pts.Count > 0 Then _stage.Emit("trace " & b.Id & " " & pts.Count & " points, newest " & Units.Pair(pts(pts.Count - 1), 3) & " m")
            Next
        End If
    End Sub
End Class
