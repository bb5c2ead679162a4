Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>One broken invariant: which, in which run (solver and sampling interval), first seen when, and what was seen.</summary>
    Friend NotInheritable Class Violation
        Friend Sub New(invariant As String, solver As String, sample As Double, time As Double, message As String)
            Me.Invariant = invariant
            Me.Solver = solver
            Me.Sample = sample
            Me.Time = time
            Me.Message = message
        End Sub

        ''' <summary>One of <see cref="Invariants"/>.</summary>
        Friend ReadOnly Property Invariant As String
        ''' <summary>event, euler or verlet.</summary>
        Friend ReadOnly Property Solver As String
        ''' <summary>The sampling interval of the run that showed it, s.</summary>
        Friend ReadOnly Property Sample As Double
        ''' <summary>The sample time at which it was first seen, s.</summary>
        Friend ReadOnly Property Time As Double
        Friend ReadOnly Property Message As String

        Public Overrides Function ToString() As String
            Return Invariant & " (" & Solver & ", sample " & Sample.ToString("R", CultureInfo.InvariantCulture) & " s) at t = " &
                Time.ToString("R", CultureInfo.InvariantCulture) & " s: " & Message
        End Function
    End Class
End Namespace
