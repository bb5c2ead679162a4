Option Strict On

''' <summary>
''' Zoom, pan and follow on the canvas. The wheel zooms about the cursor (the point under it stays
''' under it), a drag with the middle button pans, and a click with the middle button on a body
''' follows it: the view keeps it in the middle as it moves (π from collisions, the head-on lessons:
''' the bodies leave the middle of a large box). The camera is a zoom and the point of the
''' container at the middle of the canvas; zoom 1 is the whole container, fitted.
''' </summary>
Friend NotInheritable Class CameraView
    ''' <summary>The closest zoom: 20 times the fitted container.</summary>
    Public Const MaxZoom As Double = 20.0
    ''' <summary>What one notch of the wheel zooms by.</summary>
    Public Const NotchFactor As Double = 1.25
    ''' <summary>The zoom following a body starts at when the view shows the whole container: close enough to follow.</summary>
    Public Const FollowZoom As Double = 3.0

    Private ReadOnly _stage As Stage
    Private _centre As Vector ' m: the point of the container at the middle of the canvas
    Private _panFrom As Vector? ' px: where the middle button went down
    Private _panCentre As Vector ' m: the centre when it went down
    Private _panMoved As Boolean

    Public Sub New(stage As Stage)
        _stage = stage
    End Sub

    ''' <summary>How many times the fitted container the view is (1: the whole container).</summary>
    Public ReadOnly Property Zoom As Double = 1.0

    ''' <summary>The body the view follows, or Nothing.</summary>
    Public ReadOnly Property Followed As Shape

    ''' <summary>Whether the view is the plain fitted container (no zoom, no pan, nothing followed).</summary>
    Public ReadOnly Property IsFitted As Boolean
        Get
            Return Zoom = 1.0 AndAlso Followed Is Nothing
        End Get
    End Property

    ''' <summary>The view through the camera, from the fitted one (<paramref name="fitted"/>: the whole container in the canvas).</summary>
    Public Function Apply(fitted As ViewTransform) As ViewTransform
        If fitted Is Nothing Then Throw New ArgumentNullException(NameOf(fitted))
        If IsFitted Then Return fitted
        Dim w = _stage.World
        Dim middle = fitted.ToScreen(New Vector(w.Width / 2, w.Height / 2))
        Dim scale = fitted.Scale * Zoom
        Dim c = If(Followed IsNot Nothing, Clamp(Followed.CentreOfMass), _centre)
        Return New ViewTransform(scale, middle.X - c.X * scale, middle.Y + c.Y * scale)
    End Function

    ''' <summary>A point of the container, kept within it (the view never wanders off the box).</summary>
    Private Function Clamp(p As Vector) As Vector
        Dim w = _stage.World
        If Not p.IsFinite Then Return New Vector(w.Width / 2, w.Height / 2)
        Return New Vector(Math.Max(0, Math.Min(w.Width, p.X)), Math.Max(0, Math.Min(w.Height, p.Y)))
    End Function

    ''' <summary>
    ''' Zooms by <paramref name="notches"/> of the wheel (in, when positive) about the canvas point
    ''' (<paramref name="x"/>, <paramref name="y"/>) px: the point of the scene under it stays under
    ''' it, as far as the zoom allows (1 to <see cref="MaxZoom"/>). Back at 1 the view is the fitted
    ''' container again. Returns whether the view changed.
    ''' </summary>
    Public Function ZoomAt(notches As Double, x As Double, y As Double, fitted As ViewTransform) As Boolean
        If fitted Is Nothing Then Throw New ArgumentNullException(NameOf(fitted))
        If Double.IsNaN(notches) OrElse notches = 0 Then Return False
        Dim before = Apply(fitted)
        Dim p = before.ToWorld(x, y)
        Dim z = Math.Max(1.0, Math.Min(MaxZoom, Zoom * Math.Pow(NotchFactor, notches)))
        If z = Zoom Then Return False
        _Zoom = z
        If z = 1.0 Then
            _Followed = Nothing
            Return True
        End If
        If Followed IsNot Nothing Then Return True ' the followed body stays in the middle
        Dim w = _stage.World
        Dim middle = fitted.ToScreen(New Vector(w.Width / 2, w.Height / 2))
        Dim scale = fitted.Scale * z
        _centre = Clamp(New Vector(p.X - (x - middle.X) / scale, p.Y + (y - middle.Y) / scale))
        Return True
    End Function

    ''' <summary>The middle button went down at (x, y) px: a pan, or a click that follows a body, begins.</summary>
    Public Sub BeginPan(x As Double, y As Double, fitted As ViewTransform)
        _panFrom = New Vector(x, y)
        _panMoved = False
        Dim current = Apply(fitted)
        Dim w = _stage.World
        Dim middle = fitted.ToScreen(New Vector(w.Width / 2, w.Height / 2))
        _panCentre = current.ToWorld(middle.X, middle.Y)
    End Sub

    ''' <summary>Whether the middle button is down (a pan in progress).</summary>
    Public ReadOnly Property IsPanning As Boolean
        Get
            Return _panFrom.HasValue
        End Get
    End Property

    ''' <summary>The middle button moved to (x, y) px: the scene moves with it (zoomed in; the fitted container stays put). Returns whether the view changed.</summary>
    Public Function PanTo(x As Double, y As Double, fitted As ViewTransform) As Boolean
        If Not _panFrom.HasValue OrElse Zoom = 1.0 Then Return False
        Dim d = New Vector(x, y) - _panFrom.Value
        If d.Length < 4 AndAlso Not _panMoved Then Return False
        _panMoved = True
        _Followed = Nothing ' a pan takes the view from the followed body
        Dim scale = fitted.Scale * Zoom
        _centre = Clamp(New Vector(_panCentre.X - d.X / scale, _panCentre.Y + d.Y / scale))
        Return True
    End Function

    ''' <summary>
    ''' The middle button came up: the end of a pan, or (when it did not move) a click that follows
    ''' <paramref name="body"/>; a click on the body followed, or on no body, stops following.
    ''' Returns the body followed now, or Nothing.
    ''' </summary>
    Public Function EndPan(body As Shape) As Shape
        Dim wasClick = _panFrom.HasValue AndAlso Not _panMoved
        _panFrom = Nothing
        If Not wasClick Then Return Followed
        Follow(If(body Is Followed, Nothing, body))
        Return Followed
    End Function

    ''' <summary>Follows <paramref name="body"/> (moving or fixed), zooming in to <see cref="FollowZoom"/> when the view shows the whole container; Nothing stops following, keeping the zoom.</summary>
    Public Sub Follow(body As Shape)
        If body Is Nothing Then
            If Followed IsNot Nothing Then _centre = Clamp(Followed.CentreOfMass)
            _Followed = Nothing
            Return
        End If
        _Followed = body
        If Zoom < FollowZoom Then _Zoom = FollowZoom
    End Sub

    ''' <summary>Back to the whole container: zoom 1, nothing followed.</summary>
    Public Sub Reset()
        _Zoom = 1.0
        _Followed = Nothing
        _panFrom = Nothing
    End Sub

    ''' <summary>A new world is on show (a scene, a checkpoint, Undo): the followed body is followed in it by its id, if it is there.</summary>
    Public Sub FollowWorld(w As World)
        If w Is Nothing Then Throw New ArgumentNullException(NameOf(w))
        If Followed IsNot Nothing Then _Followed = w.Find(Followed.Id)
    End Sub
End Class
