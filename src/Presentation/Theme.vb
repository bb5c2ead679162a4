Option Strict On

''' <summary>
''' The canvas colours (&amp;HRRGGBB) and text size: the normal light theme, and a high-contrast
''' dark one for projectors in bright rooms.
''' </summary>
Public NotInheritable Class Theme
    ''' <summary>Near-white canvas, dark ink.</summary>
    Public Shared ReadOnly Property Light As New Theme(&HFAFAFA, &H101010, &HD0D0D0, &H1565C0, &HC62828, &H2E7D32, &HF57F17, False)
    ''' <summary>Black canvas, white ink, bright accents.</summary>
    Public Shared ReadOnly Property Dark As New Theme(&H0, &HFFFFFF, &H505050, &H40C4FF, &HFF5252, &H69F0AE, &HFFFF00, True)

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
    ''' <summary>Faint lines (the area outside the container).</summary>
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
End Class
