Option Strict On
Imports System.Globalization
Imports PhysicsEngine

''' <summary>
''' Scenes that every build of the engine must run alike, and the record of one run to the last bit:
''' every collision (time, who, velocities before and after) and then every circle's final state, one
''' line each, doubles as their 64 bits in hex. The net10.0 build runs them with the vectorised pair
''' test and with the one-at-a-time one; the netstandard2.0 build (the app's, under Mono or .NET
''' Framework) has only the latter. This file is compiled into both test programs.
''' </summary>
Friend Module CollisionLog
    ''' <summary>
    ''' An elastic gas (every pair on the hot path), a settling pile (resting, sleeping, waking), a
    ''' mixed scene (rectangles, fixed circles, corners), and balls rolling off tables (slides round
    ''' a corner: the only place the solver calls Math.Cos, Sin and Acos).
    ''' </summary>
    Friend ReadOnly SceneNames As String() = {"gas", "pile", "mixed", "tables"}

    ''' <summary>Simulated time each scene runs (s), in frames of <see cref="Frame"/> as the app advances.</summary>
    Private Function Duration(scene As String) As Double
        Select Case scene
            Case "gas" : Return 1.0
            Case "pile", "tables" : Return 3.0
            Case Else : Return 2.0
        End Select
    End Function

    Private Const Frame As Double = 0.05

    ''' <summary>The named scene, built afresh (seeded: the same scene on every build).</summary>
    Friend Function Build(scene As String) As World
        Select Case scene
            Case "gas"
                Return Scenarios.ElasticGas(300, 0.3, seed:=1)
            Case "pile"
                Return Scenarios.Pile(120, 0.3, seed:=1)
            Case "mixed"
                Dim w As New World(6, 4, 9.81, 0.9)
                w.Add(New Rectangle(New Vector(1, 0.5), 1.5, 0.3))
                w.Add(New Rectangle(New Vector(3.5, 1.2), 0.2, 1.5))
                w.Add(Circle.CreateFixed(New Vector(2.5, 2.0), 0.3))
                w.Add(Circle.CreateFixed(New Vector(5, 1.0), 0.15))
                Dim rng As New Random(26)
                For k = 1 To 200
                    w.Add(New Circle(New Vector(rng.NextDouble() * 6, 2 + rng.NextDouble() * 2), 0.02 + 0.04 * rng.NextDouble(), 1.0,
                                     New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)))
                Next
                Return w
            Case "tables"
                ' Two tables; balls on them rolling towards the edges, slower than √(g r) (they
                ' slide round the corner) and faster (they fly off), and a few dropped onto them.
                Dim w As New World(6, 4, 9.81, 0.5)
                w.Add(New Rectangle(New Vector(0, 0), 2, 1))
                w.Add(New Rectangle(New Vector(4, 0), 2, 1.5))
                For k = 0 To 7
                    Dim r = 0.04 + 0.005 * k
                    w.Add(New Circle(New Vector(0.2 + 0.22 * k, 1 + r), r, 1.0, New Vector(0.1 + 0.1 * k, 0)))
                    w.Add(New Circle(New Vector(4.2 + 0.22 * k, 1.5 + r), r, 1.0, New Vector(-0.1 - 0.1 * k, 0)))
                Next
                For k = 0 To 3
                    w.Add(New Circle(New Vector(0.5 + 0.4 * k, 2.5), 0.05, 1.0, New Vector(0.3, 0)))
                    w.Add(New Circle(New Vector(4.3 + 0.4 * k, 3.0), 0.05, 1.0, New Vector(-0.3, 0)))
                Next
                Return w
            Case Else
                Throw New ArgumentException("no scene " & scene, NameOf(scene))
        End Select
    End Function

    ''' <summary>
    ''' Runs the scene with the event solver and returns its record. <paramref name="vectorScan"/>
    ''' picks the pair test on the net10.0 build; the netstandard2.0 build has only the
    ''' one-at-a-time test.
    ''' </summary>
    Friend Function Record(scene As String, vectorScan As Boolean) As List(Of String)
        Dim w = Build(scene)
        Dim s = UseEventSolver(w)
#If NET Then
        s.VectorScan = vectorScan
#Else
        If vectorScan Then Throw New PlatformNotSupportedException("this build has no vectorised pair test")
#End If
        ' The same grid for every run: each pair test would otherwise choose its own cell size.
        s.CellOccupancy = 2.0
        Dim index As New Dictionary(Of Shape, Integer)()
        For k = 0 To w.Bodies.Count - 1
            index(w.Bodies(k)) = k
        Next
        Dim lines As New List(Of String)()
        w.CollisionListener =
            Sub(r)
                Dim other = If(r.B Is Nothing, "wall:" & r.Wall.ToString().ToLowerInvariant(), index(r.B).ToString(CultureInfo.InvariantCulture))
                lines.Add(String.Join(" ", "collision", Bits(r.Time), index(r.A).ToString(CultureInfo.InvariantCulture), other, r.KindName,
                                      Bits(r.AVelocityBefore.X), Bits(r.AVelocityBefore.Y), Bits(r.AVelocityAfter.X), Bits(r.AVelocityAfter.Y),
                                      Bits(r.BVelocityBefore.X), Bits(r.BVelocityBefore.Y), Bits(r.BVelocityAfter.X), Bits(r.BVelocityAfter.Y)))
            End Sub
        Dim frames = CInt(Math.Round(Duration(scene) / Frame))
        For k = 1 To frames
            w.Advance(Frame)
        Next
        For Each c In w.Circles
            lines.Add(String.Join(" ", "final", index(c).ToString(CultureInfo.InvariantCulture),
                                  Bits(c.Position.X), Bits(c.Position.Y), Bits(c.Velocity.X), Bits(c.Velocity.Y)))
        Next
        Return lines
    End Function

    ''' <summary>A double as its 64 bits, in hex: equal text means equal to the last bit (−0 ≠ 0).</summary>
    Friend Function Bits(value As Double) As String
        Return BitConverter.DoubleToInt64Bits(value).ToString("X16", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The double that <see cref="Bits"/> wrote.</summary>
    Friend Function FromBits(hex As String) As Double
        Return BitConverter.Int64BitsToDouble(Long.Parse(hex, NumberStyles.HexNumber, CultureInfo.InvariantCulture))
    End Function
End Module
