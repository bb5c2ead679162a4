Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>
    ''' Checks one scene with one solver: a run sampled every S, and for the event solver a second run
    ''' sampled every S₂ whose collisions and end state must equal the first's to the bit (sampling only
    ''' reads the state; it must never change the run).
    ''' </summary>
    Friend Module SceneCheck
        ''' <param name="text">physics-scene/1 text</param>
        ''' <param name="stopAt">stop at the first violation of this invariant (a shrinking probe); Nothing checks everything</param>
        ''' <param name="onRunStart">told the sampling interval before each run starts (so a parent can tell which run hung)</param>
        Friend Function Check(text As String, solver As String, plan As RunPlan, Optional stopAt As String = Nothing,
                              Optional onRunStart As Action(Of Double) = Nothing) As CheckResult
            If plan Is Nothing Then Throw New ArgumentNullException(NameOf(plan))
            Dim result As New CheckResult()
            Dim twice = solver = "event" AndAlso plan.SecondSample > 0
            onRunStart?.Invoke(plan.Sample)
            Dim first = SceneRunner.Run(text, solver, plan.Time, plan.Sample, plan.Cap, stopAt, keepLog:=twice)
            result.Violations.AddRange(first.Violations)
            result.Collisions = first.Collisions
            result.WallSeconds = first.WallSeconds
            If Not twice OrElse Not first.Completed OrElse (stopAt IsNot Nothing AndAlso result.Broke(stopAt)) Then Return result

            onRunStart?.Invoke(plan.SecondSample)
            Dim second = SceneRunner.Run(text, solver, plan.Time, plan.SecondSample, plan.Cap, stopAt, keepLog:=True)
            result.WallSeconds += second.WallSeconds
            For Each v In second.Violations
                If Not result.Broke(v.Invariant) Then result.Violations.Add(v)
            Next
            If Not second.Completed Then Return result
            Dim inv = CultureInfo.InvariantCulture
            Dim nameA = "sampled every " & plan.Sample.ToString("R", inv) & " s"
            Dim nameB = "every " & plan.SecondSample.ToString("R", inv) & " s"
            Dim time = Double.NaN
            Dim difference = CollisionLog.FirstDifference(first.Log, second.Log, nameA, nameB, time)
            If difference Is Nothing Then difference = FinalState.FirstDifference(first.Final, second.Final, nameA, nameB)
            If difference IsNot Nothing Then
                result.Violations.Add(New Violation(Invariants.Sampling, solver, plan.Sample, If(Double.IsNaN(time), plan.Time, time), difference))
            End If
            Return result
        End Function
    End Module
End Namespace
