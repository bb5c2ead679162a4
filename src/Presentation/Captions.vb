Option Strict On

''' <summary>
''' The words on the window's buttons, boxes and tabs, in one place: the window shows these, and a
''' test checks that the tutorial names no control the window does not have.
''' </summary>
Public Module Captions
    Public Const Reset As String = "Reset"
    Public Const AddCircle As String = "Add circle"
    Public Const AddRectangle As String = "Add rectangle"
    Public Const ResizeContainer As String = "Resize container"
    Public Const Fixed As String = "Fixed"
    Public Const LargeFonts As String = "Large fonts"
    Public Const HighContrast As String = "High contrast"
    Public Const Arrows As String = "Arrows"
    Public Const Tutorial As String = "Tutorial"
    Public Const MathsUsed As String = "Maths used"
    Public Const OpenScene As String = "Open…"
    Public Const SaveScene As String = "Save…"
    Public Const CollisionLog As String = "Collision log"
    Public Const AddPolygon As String = "Add polygon"
    Public Const AddRamp As String = "Add ramp"
    Public Const AddByCorners As String = "Add by corners"
    Public Const AddSpring As String = "+ Spring"
    Public Const AddRod As String = "+ Rod"
    Public Const AddString As String = "+ String"
    Public Const SetFriction As String = "Set friction"
    Public Const Grid As String = "Grid"
    ''' <summary>The liquid tool's button, which drops down water, oil or a typed density.</summary>
    Public Const Liquid As String = "Liquid ▾"

    ''' <summary>Every caption, with the changing ones (Pause/Resume, Delete mode) in their plain form.</summary>
    Public ReadOnly Property All As IReadOnlyList(Of String) = {
        "Pause", "Resume", Reset, "Delete mode", AddCircle, AddRectangle, ResizeContainer, Fixed, LargeFonts, HighContrast, Arrows, Grid,
        Tutorial, MathsUsed, OpenScene, SaveScene, "Open", "Save", CollisionLog, "Circles", "Rectangles",
        AddPolygon, AddByCorners, AddRamp, AddSpring, AddRod, AddString, SetFriction, Liquid, "Bodies", "Links",
        "Moon", "Mars", "Earth", "Jupiter"}.Concat(MomentumCaptions.All).ToArray()
End Module
