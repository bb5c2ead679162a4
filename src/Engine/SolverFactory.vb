Option Strict On

''' <summary>Makes a solver by the name the command line and the app use.</summary>
Public Module SolverFactory
    ''' <summary>The names <see cref="Create"/> accepts.</summary>
    Public ReadOnly Property Names As IReadOnlyList(Of String) = {"auto", "event", "euler", "verlet"}

    ''' <summary>
    ''' Makes the named solver. "auto" picks what the scene needs. <paramref name="timeStep"/> (s) is
    ''' the step of a stepping solver; Nothing means its default. Unknown names throw ArgumentException.
    ''' </summary>
    Public Function Create(name As String, Optional timeStep As Double? = Nothing) As ISolver
        Return Create(name, timeStep, Nothing)
    End Function

    ''' <summary>
    ''' As <see cref="Create(String, Double?)"/>, for <paramref name="world"/> (which "auto" may look at: today the
    ''' event solver takes every scene).
    ''' </summary>
    Public Function Create(name As String, timeStep As Double?, world As World) As ISolver
        Select Case name
            Case "auto", "event"
                Return New EventDrivenSolver()
            Case "euler"
                Return New SemiImplicitEulerSolver(If(timeStep, SemiImplicitEulerSolver.DefaultTimeStep))
            Case "verlet"
                Return New VerletSolver(If(timeStep, VerletSolver.DefaultTimeStep))
            Case Else
                Throw New ArgumentException("unknown solver '" & name & "' (expected one of: " & String.Join(", ", Names) & ")", NameOf(name))
        End Select
    End Function
End Module
