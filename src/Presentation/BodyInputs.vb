Option Strict On

''' <summary>
''' The text in the window's input boxes, as the presenter last accepted (and clamped) it. The
''' window writes what was typed into the presenter's Add/Resize calls and shows these back.
''' </summary>
Public NotInheritable Class BodyInputs
    ''' <summary>Circle radius, m.</summary>
    Public Property RadiusText As String = "0.25"
    ''' <summary>Circle mass, kg.</summary>
    Public Property MassText As String = "1"
    ''' <summary>Whether the next circle is fixed.</summary>
    Public Property IsFixed As Boolean
    ''' <summary>Rectangle width, m.</summary>
    Public Property WidthText As String = "1"
    ''' <summary>Rectangle height, m.</summary>
    Public Property HeightText As String = "0.5"
    ''' <summary>Container width, m.</summary>
    Public Property ContainerWidthText As String = ""
    ''' <summary>Container height, m.</summary>
    Public Property ContainerHeightText As String = ""
End Class
