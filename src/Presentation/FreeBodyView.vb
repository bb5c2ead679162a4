Option Strict On

''' <summary>
''' The free-body diagram of the chosen body (the engine's <see cref="BodyForces"/>), as the canvas and the Forces
''' tab show it: whether it is on, which body, its arrows (every force drawn from the centre of mass, as for a
''' particle: bodies here never turn, so where a force acts changes nothing), its table rows, and the line that
''' sets ΣF beside m a. The chosen body is the one picked in the Forces tab, else the first movable body.
''' </summary>
Public NotInheritable Class FreeBodyView
    ''' <summary>The tab's title and the box's caption.</summary>
    Public Const Title As String = "Forces"

    ''' <summary>The longest arrow, as a fraction of the container's smaller side.</summary>
    Public Const LongestArrowFraction As Double = 0.15

    ''' <summary>The Forces table's column headers.</summary>
    Public Shared ReadOnly Property Headers As IReadOnlyList(Of String) = {"Force", "From", "Size (N)", "Direction (°)"}

    ''' <summary>Whether the diagram is drawn on the canvas.</summary>
    Public ReadOnly Property Shown As Boolean

    ''' <summary>The id of the body chosen in the Forces tab, or Nothing for the first movable body.</summary>
    Public ReadOnly Property ChosenId As String

    ''' <summary>Draws the diagram on the canvas, or stops.</summary>
    Public Sub SetShown(value As Boolean)
        _Shown = value
    End Sub

    ''' <summary>Chooses the body by id (Nothing or empty: the first movable body).</summary>
    Public Sub Choose(id As String)
        _ChosenId = If(String.IsNullOrEmpty(id), Nothing, id)
    End Sub

    ''' <summary>The body whose forces are shown in <paramref name="world"/>: the chosen one while it is there and movable, else the first movable body; Nothing when there is none.</summary>
    Public Function BodyIn(world As World) As Shape
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If ChosenId IsNot Nothing Then
            Dim chosen = world.Movables.FirstOrDefault(Function(b) b.Id = ChosenId)
            If chosen IsNot Nothing Then Return chosen
        End If
        Return If(world.Movables.Count > 0, world.Movables(0), Nothing)
    End Function

    ''' <summary>The diagram of the body shown, now; Nothing when the world has no movable body.</summary>
    Public Function DiagramIn(world As World) As FreeBodyDiagram
        Dim body = BodyIn(world)
        If body Is Nothing Then Return Nothing
        Return BodyForces.Diagram(world, body)
    End Function

    ''' <summary>The letter a diagram writes a force with: W, N, F (friction), T, S (spring), D (drag), U (upthrust).</summary>
    Public Shared Function Symbol(kind As ForceKind) As String
        Select Case kind
            Case ForceKind.Weight : Return "W"
            Case ForceKind.Normal : Return "N"
            Case ForceKind.Friction : Return "F"
            Case ForceKind.Tension : Return "T"
            Case ForceKind.Spring : Return "S"
            Case ForceKind.Drag : Return "D"
            Case Else : Return "U"
        End Select
    End Function

    ''' <summary>The name of a force in the table: "weight", "normal", "friction", "tension", "spring", "drag", "upthrust".</summary>
    Public Shared Function Name(kind As ForceKind) As String
        Select Case kind
            Case ForceKind.Buoyancy : Return "upthrust"
            Case Else : Return kind.ToString().ToLowerInvariant()
        End Select
    End Function

    ''' <summary>A force's direction, degrees anticlockwise from +x in [0, 360).</summary>
    Public Shared Function Direction(force As Vector) As Double
        Dim degrees = Math.Atan2(force.Y, force.X) * 180 / Math.PI
        If degrees < 0 Then degrees += 360
        ' Rounding that would print 360.0 is 0.
        If degrees >= 359.95 Then degrees = 0
        Return degrees
    End Function

    ''' <summary>Metres of arrow per newton: the largest force of <paramref name="d"/> as long as <paramref name="longest"/> m.</summary>
    Public Shared Function MetresPerNewton(d As FreeBodyDiagram, longest As Double) As Double
        If d Is Nothing Then Throw New ArgumentNullException(NameOf(d))
        Dim largest = If(d.Forces.Count = 0, 0, d.Forces.Max(Function(f) f.Magnitude))
        If Not (largest > 0) Then Return 0
        Return longest / largest
    End Function

    ''' <summary>The arrows of <paramref name="d"/> for a container of <paramref name="width"/> × <paramref name="height"/> m, each from the centre of mass.</summary>
    Public Shared Function Arrows(d As FreeBodyDiagram, width As Double, height As Double) As IReadOnlyList(Of ForceArrow)
        If d Is Nothing Then Throw New ArgumentNullException(NameOf(d))
        Dim scale = MetresPerNewton(d, LongestArrowFraction * Math.Min(width, height))
        Dim start = d.Body.CentreOfMass
        Dim result As New List(Of ForceArrow)
        For Each f In d.Forces
            If Not (f.Magnitude > 0) Then Continue For
            result.Add(New ForceArrow(f.Kind, start, start + f.Force * scale, Symbol(f.Kind) & " " & Units.Quantity(f.Magnitude, "N")))
        Next
        Return result
    End Function

    ''' <summary>The Forces table's rows: the force's name, what exerts it, its size (N) and direction (°).</summary>
    Public Shared Function Rows(d As FreeBodyDiagram) As IReadOnlyList(Of String())
        If d Is Nothing Then Return Array.Empty(Of String())()
        Return d.Forces.Select(Function(f) New String() {Name(f.Kind), f.Source, Units.Sig(f.Magnitude), Units.Num(Direction(f.Force), 1)}).ToList()
    End Function

    ''' <summary>ΣF and m a, the noise of rounding beside the forces' sizes shown as 0.</summary>
    Public Shared Function SumLine(d As FreeBodyDiagram) As String
        If d Is Nothing Then Return ""
        Return "ΣF = " & Units.SigPair(Clean(d.Sum, d)) & " N    m·a = " & Units.SigPair(Clean(d.MassTimesAcceleration, d)) & " N"
    End Function

    ''' <summary>
    ''' "" or, for a body the solver holds asleep (<paramref name="asleep"/>) where the forces shown do not balance, a
    ''' sentence for the teacher on why it does not move: the exact solver puts a ball to sleep once it has settled among
    ''' bodies it then treats as fixed (in a crowd; see docs/event-driven.md §6), and without friction they would move.
    ''' </summary>
    Public Shared Function RestNote(d As FreeBodyDiagram, asleep As Boolean) As String
        If d Is Nothing OrElse Not asleep Then Return ""
        Dim sum = Clean(d.Sum, d)
        If sum = Vector.Zero Then Return ""
        Return d.Body.Id & " is at rest, but the forces shown do not balance (ΣF = " & Units.SigPair(sum) & " N): the exact solver " &
            "stopped it where it settled, holding the bodies around it as fixed. With no friction they would move, and so would it."
    End Function

    ''' <summary>For the trace: the body, each force as "N table 14.7 N 90°", ΣF and m a.</summary>
    Public Shared Function TraceLine(d As FreeBodyDiagram) As String
        If d Is Nothing Then Return "forces: no body"
        Dim parts = d.Forces.Select(Function(f) Symbol(f.Kind) & " " & f.Source & " " & Units.Num(f.Magnitude, 3) & " N " & Units.Num(Direction(f.Force), 1) & "°")
        Return "forces of " & d.Body.Id & ": " & String.Join("; ", parts) & " | sum " & Units.Pair(Clean(d.Sum, d), 3) & " N ma " & Units.Pair(Clean(d.MassTimesAcceleration, d), 3) & " N"
    End Function

    ''' <summary><paramref name="v"/> with each part that is rounding beside the largest force set to 0.</summary>
    Private Shared Function Clean(v As Vector, d As FreeBodyDiagram) As Vector
        Dim scale = If(d.Forces.Count = 0, 0, d.Forces.Max(Function(f) f.Magnitude))
        ' The solve keeps ΣF = m a to about 10⁻¹² of the forces; a millionth is far below the figures shown.
        scale *= 1000
        Return New Vector(Units.AtNoise(v.X, scale), Units.AtNoise(v.Y, scale))
    End Function
End Class
