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

    ''' <summary>
    ''' Writes the forces of the body shown to the trace and, when it is asleep where they do not balance, says in the
    ''' message why it does not move (<see cref="FreeBodyView.RestNote"/>). The diagram is found once for both.
    ''' </summary>
    Private Sub EmitAndExplainForces()
        Dim d = ForcesDiagram()
        Emit(FreeBodyView.TraceLine(d))
        If d Is Nothing Then Return
        Dim exact = TryCast(TimelineSolver.Unwrap(World.Solver), EventDrivenSolver)
        Dim note = FreeBodyView.RestNote(d, exact IsNot Nothing AndAlso exact.IsAsleep(d.Body))
        If note.Length > 0 Then ShowMessage(note)
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
