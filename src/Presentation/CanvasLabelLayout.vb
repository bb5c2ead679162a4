Option Strict On

''' <summary>
''' Where every label of the canvas goes, so that none covers another, a body, the centre of mass's
''' marker or the momentum panel: the centre of mass and Σp first, then the bodies' ids (inside a
''' ball when they fit there), then the impulses' Δp; each tries the places round what it names and
''' is left out when none is free (see <see cref="LabelPlacer"/>). The painter draws what this gives;
''' tests check it for overlaps in the crowded lessons.
''' </summary>
Public NotInheritable Class CanvasLabelLayout
    Private Sub New()
    End Sub

    ''' <summary>With more balls than this no ids are drawn (a gas): the frame rate matters more.</summary>
    Public Const MaxLabelledCircles As Integer = 60
    ''' <summary>The most impulse marks labelled at once.</summary>
    Public Const MaxImpulseLabels As Integer = 16
    ''' <summary>The least radius a ball is drawn with, in 96-dpi pixels (the painter's too).</summary>
    Public Const MinBallPixels As Double = 2
    ''' <summary>The centre of mass's marker's radius, in 96-dpi pixels (the painter's too).</summary>
    Public Const MarkerPixels As Double = 8

    ''' <summary>
    ''' Places the labels of the scene on show in a canvas of <paramref name="width"/> ×
    ''' <paramref name="height"/> px, their sizes from <paramref name="measure"/> (px), with
    ''' <paramref name="k"/> screen pixels per 96-dpi pixel.
    ''' </summary>
    Public Shared Function Lay(p As SimulationPresenter, measure As Func(Of String, (Width As Double, Height As Double)), k As Double, width As Integer, height As Integer) As IReadOnlyList(Of CanvasLabel)
        If p Is Nothing Then Throw New ArgumentNullException(NameOf(p))
        If measure Is Nothing Then Throw New ArgumentNullException(NameOf(measure))
        Dim view = p.View
        Dim world = p.World
        Dim result As New List(Of CanvasLabel)
        Dim placer As New LabelPlacer(New LabelBox(0, 0, width, Math.Max(1, height - p.ScaleStripPixels)))
        ' Every body is an obstacle (a ramp is a thin line: labels may cross it).
        For Each b In world.Bodies
            If b.Kind = ShapeKind.Segment Then Continue For
            placer.AddObstacle(ScreenBox(b, view, k), b)
        Next
        Dim panel = p.MomentumPanelPixels
        Dim panelBox = New LabelBox(width - panel, 0, panel, height)
        If panel > 0 Then placer.AddObstacle(panelBox)
        Dim canvas = New LabelBox(0, 0, width, Math.Max(1, height - p.ScaleStripPixels))
        Dim gap = 3 * k

        ' The centre of mass and Σp: few, and what the momentum lessons are about.
        Dim summary = p.Momentum
        If summary.HasBodies AndAlso (p.ShowCentreOfMass OrElse p.ShowTotalMomentum) Then
            Dim c = view.ToScreen(summary.CentreOfMass)
            Dim marker = LabelBox.AroundCircle(c.X, c.Y, MarkerPixels * k)
            If p.ShowCentreOfMass Then
                placer.AddObstacle(marker)
                Add(result, placer, "CM", CanvasLabelKind.CentreOfMass, marker, measure, gap, Nothing)
            End If
            If p.ShowTotalMomentum Then
                Dim ppu = p.MomentumArrows.PixelsPerUnit
                Dim tip = New LabelBox(c.X + summary.Momentum.X * ppu - 2 * k, c.Y - summary.Momentum.Y * ppu - 2 * k, 4 * k, 4 * k)
                Add(result, placer, "Σp", CanvasLabelKind.TotalMomentum, tip, measure, gap, Nothing)
            End If
        End If

        ' The free-body diagram: each force at its arrow's tip, and ΣF beside m a by the body.
        If p.Forces.Shown Then
            Dim d = p.ForcesDiagram()
            If d IsNot Nothing Then
                For Each a In FreeBodyView.Arrows(d, world.Width, world.Height)
                    Dim t = view.ToScreen(a.Tip)
                    Add(result, placer, a.Label, CanvasLabelKind.Force, New LabelBox(t.X - 2 * k, t.Y - 2 * k, 4 * k, 4 * k), measure, gap, d.Body)
                Next
                Add(result, placer, FreeBodyView.SumLine(d), CanvasLabelKind.ForceSum, ScreenBox(d.Body, view, k), measure, gap, d.Body)
            End If
        End If

        ' The bodies' ids: inside a ball or a box when they fit there, else round it. A fixed ball's
        ' middle holds the cross that marks it fixed: its id goes round it, never over the cross.
        If world.Circles.Count <= MaxLabelledCircles Then
            For Each b In world.Bodies
                If b.Kind = ShapeKind.Segment OrElse (b.IsFixed AndAlso b.Kind = ShapeKind.Rectangle) Then Continue For
                Dim box = ScreenBox(b, view, k)
                Dim size = measure(b.Id)
                If Not b.IsFixed AndAlso size.Width < box.Width - 2 AndAlso size.Height < box.Height Then
                    Dim inside As New LabelBox(box.X + (box.Width - size.Width) / 2, box.Y + (box.Height - size.Height) / 2, size.Width, size.Height)
                    ' A ball that has flown under the momentum panel, or off the canvas, keeps its id to itself.
                    If (panel > 0 AndAlso inside.Overlaps(panelBox)) OrElse Not inside.IsInside(canvas) Then Continue For
                    placer.AddFixed(inside)
                    result.Add(New CanvasLabel(b.Id, CanvasLabelKind.Body, inside, True, b))
                Else
                    Add(result, placer, b.Id, CanvasLabelKind.Body, box, measure, gap, b)
                End If
            Next
        End If

        ' The impulses, newest first: in a cradle they come all at once, and only those with room are labelled.
        If p.ShowImpulses Then
            Dim ppu = p.MomentumArrows.PixelsPerUnit
            Dim labelled = 0
            Dim marks = p.Impulses.Marks
            For i = marks.Count - 1 To 0 Step -1
                Dim m = marks(i)
                If Not m.IsLocated OrElse ImpulseMarks.Opacity(m) <= 0.5 Then Continue For
                If labelled >= MaxImpulseLabels Then Exit For
                Dim a = view.ToScreen(m.At)
                Dim tip = New LabelBox(a.X + m.Impulse.X * ppu - 2 * k, a.Y - m.Impulse.Y * ppu - 2 * k, 4 * k, 4 * k)
                If Add(result, placer, "Δp", CanvasLabelKind.Impulse, tip, measure, gap, m.Body) Then labelled += 1
            Next
        End If
        Return result
    End Function

    ''' <summary>Places one label round <paramref name="anchor"/>; returns whether it found room.</summary>
    Private Shared Function Add(result As List(Of CanvasLabel), placer As LabelPlacer, text As String, kind As CanvasLabelKind, anchor As LabelBox,
                                measure As Func(Of String, (Width As Double, Height As Double)), gap As Double, body As Shape) As Boolean
        Dim size = measure(text)
        Dim box = placer.Place(LabelPlacer.Around(anchor, size.Width, size.Height, gap))
        If Not box.HasValue Then Return False
        result.Add(New CanvasLabel(text, kind, box.Value, False, body))
        Return True
    End Function

    ''' <summary>A body's rectangle on the screen, px (a ball as drawn, never smaller than <see cref="MinBallPixels"/>).</summary>
    Public Shared Function ScreenBox(b As Shape, view As ViewTransform, k As Double) As LabelBox
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        If view Is Nothing Then Throw New ArgumentNullException(NameOf(view))
        If b.Kind = ShapeKind.Circle Then
            Dim s = view.ToScreen(b.Position)
            Dim r = Math.Max(MinBallPixels * k, view.ToPixels(DirectCast(b, Circle).Radius))
            Return LabelBox.AroundCircle(s.X, s.Y, r)
        End If
        Dim topLeft = view.ToScreen(New Vector(b.BoundsMin.X, b.BoundsMax.Y))
        Return New LabelBox(topLeft.X, topLeft.Y, view.ToPixels(b.BoundsMax.X - b.BoundsMin.X), view.ToPixels(b.BoundsMax.Y - b.BoundsMin.Y))
    End Function
End Class
