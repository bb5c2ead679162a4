Option Strict On

' The free-body diagram of a chosen body (FreeBodyView): on the canvas when Forces is ticked, and in the Forces tab.
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>Which body's forces are shown, and whether on the canvas.</summary>
    Public ReadOnly Property Forces As New FreeBodyView()

    ''' <summary>The free-body diagram on the canvas on or off; the trace gets the forces when it goes on.</summary>
    Public Sub SetShowForces(value As Boolean)
        Forces.SetShown(value)
        Emit("forces " & If(value, "on", "off"))
        If value Then EmitAndExplainForces()
    End Sub

    ''' <summary>Shows the forces of the body with <paramref name="id"/> (empty: the first movable body).</summary>
    Public Sub ChooseForcesBody(id As String)
        Forces.Choose(id)
        EmitAndExplainForces()
    End Sub

    ''' <summary>Whether the body shown was, at the last frame that looked, asleep where its forces do not balance.</summary>
    Private _forcesNoted As Boolean

    ''' <summary>The Forces tab came into view: when the body shown is asleep where its forces do not balance, the message says why.</summary>
    Public Sub ExplainForces()
        Explain(ForcesDiagram())
    End Sub

    ''' <summary>
    ''' Writes the forces of the body shown to the trace and, when it is asleep where they do not balance, says in the
    ''' message why it does not move (<see cref="FreeBodyView.RestNote"/>). The diagram is found once for both.
    ''' </summary>
    Private Sub EmitAndExplainForces()
        Dim d = ForcesDiagram()
        Emit(FreeBodyView.TraceLine(d))
        Explain(d)
    End Sub

    ''' <summary>Says in the message why the body of diagram <paramref name="d"/> does not move, if it is asleep where its forces do not balance.</summary>
    Private Sub Explain(d As FreeBodyDiagram)
        Dim note = ForcesRestNote(d)
        _forcesNoted = note.Length > 0
        If _forcesNoted Then ShowMessage(note)
    End Sub

    ''' <summary>The rest note for diagram <paramref name="d"/> (empty: none, or no diagram).</summary>
    Private Function ForcesRestNote(d As FreeBodyDiagram) As String
        If d Is Nothing Then Return ""
        Return FreeBodyView.RestNote(d, IsAsleep(d.Body))
    End Function

    ''' <summary>Whether the exact solver (inside the time machine's wrapper) holds <paramref name="body"/> asleep.</summary>
    Private Function IsAsleep(body As Shape) As Boolean
        Dim exact = TryCast(TimelineSolver.Unwrap(World.Solver), EventDrivenSolver)
        Return exact IsNot Nothing AndAlso exact.IsAsleep(body)
    End Function

    ''' <summary>
    ''' After a frame of the run, while the forces are drawn on the canvas: the body shown has just gone to sleep where
    ''' its forces do not balance (it was chosen before): the message says why, once, as choosing it then would. Its
    ''' diagram is found only while it is asleep, not every frame.
    ''' </summary>
    Private Sub FollowForcesRest()
        If Not Forces.Shown Then Return
        Dim note = If(IsAsleep(Forces.BodyIn(World)), ForcesRestNote(ForcesDiagram()), "")
        Dim noted = note.Length > 0
        If noted AndAlso Not _forcesNoted Then ShowMessage(note)
        _forcesNoted = noted
    End Sub

    ''' <summary>The diagram of the body shown, now; Nothing when there is no movable body.</summary>
    Public Function ForcesDiagram() As FreeBodyDiagram
        Return Forces.DiagramIn(World)
    End Function

    ''' <summary>The ids of the bodies whose forces can be shown (the movable ones), in the world's order.</summary>
    Public Function ForcesBodies() As IReadOnlyList(Of String)
        Return World.Movables.Select(Function(b) b.Id).ToList()
    End Function

    ''' <summary>The diagram's arrows (m) while Forces is on; none when it is off or there is no movable body.</summary>
    Public Function ForceArrows() As IReadOnlyList(Of ForceArrow)
        If Not Forces.Shown Then Return Array.Empty(Of ForceArrow)()
        Dim d = ForcesDiagram()
        If d Is Nothing Then Return Array.Empty(Of ForceArrow)()
        Return FreeBodyView.Arrows(d, World.Width, World.Height)
    End Function

    ''' <summary>Writes the forces of the body shown to the trace.</summary>
    Public Sub EmitForces()
        Emit(FreeBodyView.TraceLine(ForcesDiagram()))
    End Sub
End Class
