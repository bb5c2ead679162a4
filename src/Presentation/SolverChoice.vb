Option Strict On

''' <summary>
''' The solvers a teacher can choose in the window, each with a line saying what it is for: the
''' benchmark's question (which method, for which scene) asked in the lesson. The same start run
''' with two of them shows what the choice does.
''' </summary>
Public Module SolverChoice
    ''' <summary>The solver every new scene starts with: the exact one, which hands a scene it cannot move (chains of links) to Verlet, and says so.</summary>
    Public Const Automatic As String = "auto"

    ''' <summary>The solvers offered, in menu order.</summary>
    Public ReadOnly Property Names As IReadOnlyList(Of String) = {"event", "verlet", "euler"}

    ''' <summary>"Event-driven (exact)": the solver's name as the window shows it.</summary>
    Public Function Title(name As String) As String
        Select Case name
            Case "event", Automatic : Return "Event-driven (exact)"
            Case "verlet" : Return "Verlet (fixed step)"
            Case "euler" : Return "Euler (fixed step)"
        End Select
        Return If(name, "")
    End Function

    ''' <summary>"Event-driven (exact) — every collision at its instant": a menu line, short enough to stay on a screen.</summary>
    Public Function MenuLine(name As String) As String
        Return Title(name) & " — " & ShortPurpose(name)
    End Function

    ''' <summary>"every collision at its exact instant": what the solver is for, in a few words.</summary>
    Public Function ShortPurpose(name As String) As String
        Select Case name
            Case "event", Automatic : Return "every collision at its exact instant"
            Case "verlet" : Return "small steps: for links, piles, springs"
            Case "euler" : Return "the simplest steps: errors pile up"
        End Select
        Return ""
    End Function

    ''' <summary>"Solver: exact ▾": the caption of the button that chooses it, short enough for the row above the tables.</summary>
    Public Function ButtonCaption(name As String) As String
        Dim word As String
        Select Case name
            Case "event", Automatic : word = "exact"
            Case "verlet" : word = "Verlet"
            Case "euler" : word = "Euler"
            Case Else : word = If(name, "")
        End Select
        Return "Solver: " & word & " ▾"
    End Function

    ''' <summary>One line on what the solver is for.</summary>
    Public Function Purpose(name As String) As String
        Select Case name
            Case "event", Automatic
                Return "works out the instant of every collision and jumps from one to the next: exact, the one for collisions, momentum and π; slow when thousands of contacts come at once"
            Case "verlet"
                Return "moves every body in small equal steps of time: handles chains of links, piles and springs; energy stays close to right, but a contact is found up to a step late"
            Case "euler"
                Return "the simplest stepping method, small equal steps: fast, but its errors pile up (energy wanders): shows why the step and the method matter"
        End Select
        Return ""
    End Function

    ''' <summary>
    ''' "" or, when <paramref name="world"/> runs with a stepping solver (Verlet, Euler) and has a spring too stiff
    ''' for its step (ω h ≥ 2, see <see cref="StepStability"/>), a sentence for a teacher saying so: "Spring s is
    ''' too stiff for this step: ω h = 4.5 …, and a step method is stable only below 2, so its swing will grow
    ''' without bound. The exact solver follows it."
    ''' </summary>
    Public Function StiffSpringWarning(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim h = world.Solver?.TimeStep
        If Not h.HasValue Then Return ""
        Dim worst = StepStability.Stiffest(world, h.Value)
        If worst.Spring Is Nothing OrElse worst.OmegaH < StepStability.Limit Then Return ""
        Return "Spring " & worst.Spring.Id & " is too stiff for this step: ω h = " & Units.Sig(worst.OmegaH, 2) &
            " (how fast it swings, ω = " & Units.Quantity(worst.OmegaH / h.Value, "rad/s") & ", times the step h = " & Units.Quantity(h.Value * 1000, "ms") &
            "), and a step method is stable only below 2, so its swing will grow without bound. The exact solver follows it."
    End Function

    ''' <summary>"", or a space and <see cref="StiffSpringWarning"/>: what a message about the run adds.</summary>
    Friend Function StiffSpringAddendum(world As World) As String
        Dim warning = StiffSpringWarning(world)
        Return If(warning.Length = 0, "", " " & warning)
    End Function
End Module
