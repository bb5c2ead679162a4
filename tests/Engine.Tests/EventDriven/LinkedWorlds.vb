Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Tests.Links

Namespace EventDriven
    ''' <summary>
    ''' The worlds and pendulums that the linked-solver tests build their scenes in: a box 10 m square under
    ''' g = 9.81 m/s² with a solver, and a pendulum (a bob of radius 0.05 m on a rod or string) whose links make
    ''' the scene one for the linked solver.
    ''' </summary>
    Friend Module LinkedWorlds
        ''' <summary>Gravity in every world here, m/s².</summary>
        Friend Const G As Double = 9.81

        ''' <summary>
        ''' A world 10 m square, g = <see cref="G"/>, with coefficient of restitution <paramref name="restitution"/> and the
        ''' named solver; a stepping solver takes the step <paramref name="dt"/> (s), the event solver none.
        ''' </summary>
        Friend Function NewWorld(solver As String, restitution As Double, Optional dt As Double = 0.001) As World
            Dim w As New World(10, 10, G, restitution)
            w.Solver = If(solver = "event", SolverFactory.Create("event"), SolverFactory.Create(solver, dt))
            Return w
        End Function

        ''' <summary>
        ''' Adds a bob "bob" (radius 0.05 m, <paramref name="mass"/> kg) at rest at angle <paramref name="theta"/> (rad) from
        ''' the downward vertical, on a <paramref name="kind"/> of <paramref name="length"/> m from <paramref name="anchor"/>.
        ''' </summary>
        Friend Function AddPendulum(w As World, kind As LinkKind, anchor As Vector, length As Double, theta As Double, mass As Double) As Circle
            Dim bob As New Circle(OnCircle(anchor, length, theta), 0.05, mass, Vector.Zero, "bob")
            w.Add(bob)
            w.Add(Link.CreateTie(kind, bob, anchor, length))
            Return bob
        End Function

        ''' <summary>
        ''' A pendulum swinging in the far top-right corner (0.5 kg on a 0.5 m rod from (9, 9.5) m, released level),
        ''' so that the scene has links and the linked solver runs it, out of the way of what is tested.
        ''' </summary>
        Friend Function AddFarPendulum(w As World) As Circle
            Return AddPendulum(w, LinkKind.Rod, New Vector(9, 9.5), 0.5, Math.PI / 2, 0.5)
        End Function
    End Module
End Namespace
