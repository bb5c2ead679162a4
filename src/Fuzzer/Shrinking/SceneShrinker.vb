Option Strict On
Imports PhysicsEngine.Fuzzing.Checking

Namespace Shrinking
    ''' <summary>
    ''' Shrinks a failing scene: first the run is cut to end at the sample where the failure was first
    ''' seen (cheaper probes), then the bodies are cut by delta debugging to the fewest that still fail the
    ''' same invariant, then the run is cut again for the smaller scene. A run up to a sample time is the
    ''' same run as a longer one up to that time (the same advances), so the cut keeps the failure.
    ''' </summary>
    Friend Module SceneShrinker
        ''' <param name="plan">the run that showed it: its sampling interval (and second interval, for the sampling invariant)</param>
        ''' <param name="probe">runs a candidate; returns its violation of the same invariant, or Nothing when it no longer fails</param>
        ''' <param name="deadline">when to stop cutting bodies and keep what fails so far</param>
        Friend Function Shrink(doc As SceneDoc, plan As RunPlan, first As Violation, probe As Func(Of SceneDoc, RunPlan, Violation), deadline As DateTime) As ShrinkResult
            If doc Is Nothing Then Throw New ArgumentNullException(NameOf(doc))
            If probe Is Nothing Then Throw New ArgumentNullException(NameOf(probe))
            Dim probes = 0
            Dim counted = Function(d As SceneDoc, p As RunPlan) As Violation
                              probes += 1
                              Return probe(d, p)
                          End Function
            Dim seen = counted(doc, plan)
            If seen Is Nothing Then Return New ShrinkResult(doc, plan, first, probes, reproduced:=False)
            Shorten(doc, plan, seen, counted)

            Dim currentPlan = plan
            Dim kept = DeltaDebugging.Minimize(doc.Bodies, Function(subset) counted(doc.WithBodies(subset), currentPlan) IsNot Nothing, deadline)
            Dim smaller = doc.WithBodies(kept)
            Dim last = counted(smaller, plan)
            If last Is Nothing Then Return New ShrinkResult(doc, plan, seen, probes, reproduced:=True) ' a flaky failure: keep the scene that failed for sure
            Shorten(smaller, plan, last, counted)
            Return New ShrinkResult(smaller, plan, last, probes, reproduced:=True)
        End Function

        ''' <summary>
        ''' Ends the run at the first sample time at or after the failure (or one or two samples later, when
        ''' the failure needs them, as a difference between two sampling intervals may), when that still
        ''' fails. A wall-time failure is left alone: a shorter run would only make it pass.
        ''' </summary>
        Private Sub Shorten(doc As SceneDoc, ByRef plan As RunPlan, ByRef seen As Violation, probe As Func(Of SceneDoc, RunPlan, Violation))
            If seen.Invariant = Invariants.WallTime OrElse Double.IsNaN(seen.Time) Then Return
            Dim k = CLng(Math.Ceiling(seen.Time / plan.Sample - 0.000001))
            k = Math.Max(k, 1)
            For extra = 0 To 2
                Dim t = (k + extra) * plan.Sample
                If t >= plan.Time - plan.Sample * 0.000000001 Then Return
                Dim shorter = plan.WithTime(t)
                Dim v = probe(doc, shorter)
                If v IsNot Nothing Then
                    plan = shorter
                    seen = v
                    Return
                End If
            Next
        End Sub
    End Module
End Namespace
