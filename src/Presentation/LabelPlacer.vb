Option Strict On

''' <summary>
''' Places labels as map labels are placed: each label in turn (the most important first) tries a
''' few positions round what it names, in order, and takes the first that overlaps no label already
''' placed, no obstacle (bodies, panels) and stays on the canvas; when none is free it is left out
''' rather than drawn over something. Pure: boxes in, boxes out.
''' </summary>
Public NotInheritable Class LabelPlacer
    Private ReadOnly _canvas As LabelBox
    Private ReadOnly _obstacles As New List(Of (Box As LabelBox, Owner As Object))
    Private ReadOnly _placed As New List(Of LabelBox)

    ''' <param name="canvas">where labels may go, px</param>
    Public Sub New(canvas As LabelBox)
        _canvas = canvas
    End Sub

    ''' <summary>Something no label may cover (a body, a panel); <paramref name="owner"/> is what it is (a body may be covered by nothing but its own label inside it).</summary>
    Public Sub AddObstacle(box As LabelBox, Optional owner As Object = Nothing)
        _obstacles.Add((box, owner))
    End Sub

    ''' <summary>A label already where it must be (inside its own ball): later labels keep off it.</summary>
    Public Sub AddFixed(box As LabelBox)
        _placed.Add(box)
    End Sub

    ''' <summary>
    ''' The first of <paramref name="candidates"/> that is on the canvas and overlaps neither a label
    ''' placed before nor an obstacle; it is then taken. Nothing when none is free (the label is left out).
    ''' </summary>
    Public Function Place(candidates As IEnumerable(Of LabelBox)) As LabelBox?
        If candidates Is Nothing Then Throw New ArgumentNullException(NameOf(candidates))
        For Each c In candidates
            If Not c.IsInside(_canvas) Then Continue For
            If _placed.Any(Function(p) p.Overlaps(c)) Then Continue For
            If _obstacles.Any(Function(o) o.Box.Overlaps(c)) Then Continue For
            _placed.Add(c)
            Return c
        Next
        Return Nothing
    End Function

    ''' <summary>
    ''' Eight places for a label <paramref name="width"/> × <paramref name="height"/> px round
    ''' <paramref name="anchor"/>, <paramref name="gap"/> px clear of it, in the order a reader expects
    ''' them: above right first, then above left, below right, below left, right, left, above, below.
    ''' </summary>
    Public Shared Function Around(anchor As LabelBox, width As Double, height As Double, gap As Double) As IEnumerable(Of LabelBox)
        Dim midY = anchor.Y + anchor.Height / 2 - height / 2
        Dim midX = anchor.X + anchor.Width / 2 - width / 2
        Return {
            New LabelBox(anchor.Right + gap, anchor.Y - height - gap, width, height),
            New LabelBox(anchor.X - width - gap, anchor.Y - height - gap, width, height),
            New LabelBox(anchor.Right + gap, anchor.Bottom + gap, width, height),
            New LabelBox(anchor.X - width - gap, anchor.Bottom + gap, width, height),
            New LabelBox(anchor.Right + gap, midY, width, height),
            New LabelBox(anchor.X - width - gap, midY, width, height),
            New LabelBox(midX, anchor.Y - height - gap, width, height),
            New LabelBox(midX, anchor.Bottom + gap, width, height)}
    End Function
End Class
