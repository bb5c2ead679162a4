Option Strict On
Imports PhysicsEngine.Fuzzing.Checking

''' <summary>One checked scene: its seed (or file), the scene and run plan, and every violation every solver showed.</summary>
Friend NotInheritable Class SceneOutcome
    Friend Sub New(label As String, seed As Long?, doc As SceneDoc, plan As RunPlan)
        Me.Label = label
        Me.Seed = seed
        Me.Doc = doc
        Me.Plan = plan
    End Sub

    ''' <summary>How files and lines name it: its seed, or the scene file's name.</summary>
    Friend ReadOnly Property Label As String
    Friend ReadOnly Property Seed As Long?
    Friend ReadOnly Property Doc As SceneDoc
    Friend ReadOnly Property Plan As RunPlan
    Friend ReadOnly Property Violations As New List(Of Violation)
    ''' <summary>Collisions of each solver's first run, by solver.</summary>
    Friend ReadOnly Property Collisions As New Dictionary(Of String, Long)(StringComparer.Ordinal)
    ''' <summary>Wall-clock seconds of every run.</summary>
    Friend Property WallSeconds As Double

    ''' <summary>One violation per invariant (the first solver's), in the order <see cref="Invariants.All"/> lists them.</summary>
    Friend Function Failures() As List(Of Violation)
        Return Invariants.All.Select(Function(name) Violations.FirstOrDefault(Function(v) v.Invariant = name)).Where(Function(v) v IsNot Nothing).ToList()
    End Function
End Class
