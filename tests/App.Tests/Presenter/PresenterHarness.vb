Option Strict On
Imports PhysicsEngine.Presentation

''' <summary>A presenter on a known canvas with a recording view and a trace, plus pixel helpers.</summary>
Public NotInheritable Class PresenterHarness
    Public ReadOnly Property View As New RecordingView()
    Public ReadOnly Property TraceLines As New List(Of String)
    Public ReadOnly Property P As SimulationPresenter

    Public Sub New(Optional world As World = Nothing, Optional store As ISceneStore = Nothing)
        P = New SimulationPresenter(View, store, If(world, New World(8.0, 5.0, 9.81, 1.0)))
        P.Trace = Sub(l) TraceLines.Add(l)
        ' The presenter's wall clock stands still: every frame has time to finish, whatever the machine's
        ' load or the first use of code costs, so a test of what a frame does never depends on speed.
        ' The frame budget's own tests give the presenter a clock that moves (FrameBudgetTests).
        P.WallClock = Function() 0.0
        P.CanvasResized(800, 500)
    End Sub

    ''' <summary>The canvas pixel of a model point, m.</summary>
    Public Function Px(x As Double, y As Double) As Vector
        Return P.View.ToScreen(New Vector(x, y))
    End Function

    Public Sub LeftClick(x As Double, y As Double)
        Dim s = Px(x, y)
        P.PointerMove(s.X, s.Y)
        P.PointerDown(PointerButton.Left, s.X, s.Y)
        P.PointerUp(PointerButton.Left, s.X, s.Y)
    End Sub

    ''' <summary>Presses at one model point, moves through to another, releases there.</summary>
    Public Sub Drag(button As PointerButton, fromX As Double, fromY As Double, toX As Double, toY As Double, Optional tickBetween As Double = 0)
        Dim a = Px(fromX, fromY), b = Px(toX, toY)
        P.PointerDown(button, a.X, a.Y)
        For k = 1 To 5
            P.PointerMove(a.X + (b.X - a.X) * k / 5, a.Y + (b.Y - a.Y) * k / 5)
            If tickBetween > 0 Then P.Tick(tickBetween)
        Next
        P.PointerUp(button, b.X, b.Y)
    End Sub

    ''' <summary>Adds a movable circle straight to the world.</summary>
    Public Function Ball(x As Double, y As Double, Optional radius As Double = 0.2, Optional mass As Double = 1.0, Optional id As String = Nothing) As Circle
        Dim c As New Circle(New Vector(x, y), radius, mass, id:=id)
        P.World.Add(c)
        Return c
    End Function
End Class
