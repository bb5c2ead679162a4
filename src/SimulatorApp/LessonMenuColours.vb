Option Strict On
Imports System.Drawing
Imports System.Windows.Forms

''' <summary>
''' The Scenes menu's colours in the high-contrast theme: a black menu with white text, and the item
''' under the pointer on dark blue with a white border. The standard colours highlight it in a pale
''' blue, on which white text can hardly be read.
''' </summary>
Friend NotInheritable Class LessonMenuColours
    Inherits ProfessionalColorTable

    Private Shared ReadOnly Back As Color = Color.Black
    Private Shared ReadOnly Selected As Color = Color.FromArgb(&H15, &H65, &HC0)
    Private Shared ReadOnly Edge As Color = Color.White

    Public Overrides ReadOnly Property ToolStripDropDownBackground As Color
        Get
            Return Back
        End Get
    End Property

    Public Overrides ReadOnly Property ImageMarginGradientBegin As Color
        Get
            Return Back
        End Get
    End Property

    Public Overrides ReadOnly Property ImageMarginGradientMiddle As Color
        Get
            Return Back
        End Get
    End Property

    Public Overrides ReadOnly Property ImageMarginGradientEnd As Color
        Get
            Return Back
        End Get
    End Property

    Public Overrides ReadOnly Property MenuBorder As Color
        Get
            Return Edge
        End Get
    End Property

    Public Overrides ReadOnly Property MenuItemBorder As Color
        Get
            Return Edge
        End Get
    End Property

    Public Overrides ReadOnly Property MenuItemSelected As Color
        Get
            Return Selected
        End Get
    End Property

    Public Overrides ReadOnly Property MenuItemSelectedGradientBegin As Color
        Get
            Return Selected
        End Get
    End Property

    Public Overrides ReadOnly Property MenuItemSelectedGradientEnd As Color
        Get
            Return Selected
        End Get
    End Property
End Class
