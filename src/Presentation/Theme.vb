Option Strict On

''' <summary>
''' The window's colours (&amp;HRRGGBB): the normal light theme, and a high-contrast dark one for
''' projectors in bright rooms, which colours the whole window (canvas, panel, buttons, boxes,
''' tables and messages), not the canvas alone.
''' </summary>
Public NotInheritable Class Theme
    ''' <summary>Near-white canvas, dark ink, the usual grey panel.</summary>
    Public Shared ReadOnly Property Light As New Theme(&HFAFAFA, &H101010, &HD0D0D0, &H1565C0, &HC62828, &H2E7D32, &HF57F17, False) With {
        .Panel = &HEFEFEF, .PanelText = &H101010, .Button = &HE1E1E1, .Field = &HFFFFFF,
        .MessageBack = &HFFF8C4, .MessageText = &H781400, .HintText = &H696969, .Alert = &HC62828, .AlertBack = &HFFCDD2,
        .Fixed = &H78909C}
    ''' <summary>Black everywhere, white text and lines, bright accents.</summary>
    Public Shared ReadOnly Property Dark As New Theme(&H0, &HFFFFFF, &H505050, &H40C4FF, &HFF5252, &H69F0AE, &HFFFF00, True) With {
        .Panel = &H0, .PanelText = &HFFFFFF, .Button = &H202020, .Field = &H0,
        .MessageBack = &H0, .MessageText = &HFFFF00, .HintText = &HE0E0E0, .Alert = &HFF5252, .AlertBack = &H5A0000,
        .Fixed = &HB0BEC5}

    Private Sub New(background As Integer, ink As Integer, grid As Integer, arrow As Integer, arrowX As Integer,
                    arrowY As Integer, cue As Integer, isHighContrast As Boolean)
        Me.Background = background
        Me.Ink = ink
        Me.Grid = grid
        Me.Arrow = arrow
        Me.ArrowX = arrowX
        Me.ArrowY = arrowY
        Me.Cue = cue
        Me.IsHighContrast = isHighContrast
    End Sub

    ''' <summary>Canvas fill.</summary>
    Public ReadOnly Property Background As Integer
    ''' <summary>Text, container border, body outlines.</summary>
    Public ReadOnly Property Ink As Integer
    ''' <summary>Faint lines (a container without walls).</summary>
    Public ReadOnly Property Grid As Integer
    ''' <summary>Velocity arrow.</summary>
    Public ReadOnly Property Arrow As Integer
    ''' <summary>Horizontal component of the velocity arrow.</summary>
    Public ReadOnly Property ArrowX As Integer
    ''' <summary>Vertical component of the velocity arrow.</summary>
    Public ReadOnly Property ArrowY As Integer
    ''' <summary>The cue line while aiming.</summary>
    Public ReadOnly Property Cue As Integer
    ''' <summary>True for the dark, high-contrast theme (thicker lines).</summary>
    Public ReadOnly Property IsHighContrast As Boolean
    ''' <summary>The side panel, the window and the tables' background.</summary>
    Public Property Panel As Integer
    ''' <summary>Text on the panel and in the tables.</summary>
    Public Property PanelText As Integer
    ''' <summary>Buttons.</summary>
    Public Property Button As Integer
    ''' <summary>Text boxes.</summary>
    Public Property Field As Integer
    ''' <summary>The message box when it holds a message.</summary>
    Public Property MessageBack As Integer
    ''' <summary>A message's text.</summary>
    Public Property MessageText As Integer
    ''' <summary>The quiet hint shown when there is no message.</summary>
    Public Property HintText As Integer
    ''' <summary>Warnings on the canvas (DELETE MODE, PAUSED), and a blocked preview.</summary>
    Public Property Alert As Integer
    ''' <summary>The Delete mode button while it is on.</summary>
    Public Property AlertBack As Integer
    ''' <summary>The fill of fixed polygons, rectangles and ramps, and of link anchors: one colour says "this never moves".</summary>
    Public Property Fixed As Integer
End Class
