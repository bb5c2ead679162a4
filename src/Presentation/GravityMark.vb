Option Strict On

''' <summary>A named gravity on the g slider (surface gravity of a body of the Solar System).</summary>
Public NotInheritable Class GravityMark
    Private Sub New(name As String, value As Double)
        Me.Name = name
        Me.Value = value
    End Sub

    ''' <summary>"Moon", "Mars", "Earth", "Jupiter".</summary>
    Public ReadOnly Property Name As String
    ''' <summary>g, m/s².</summary>
    Public ReadOnly Property Value As Double

    ''' <summary>The marks, smallest g first (NASA planetary fact sheets, rounded).</summary>
    Public Shared ReadOnly Property All As IReadOnlyList(Of GravityMark) = {
        New GravityMark("Moon", 1.62), New GravityMark("Mars", 3.71),
        New GravityMark("Earth", 9.81), New GravityMark("Jupiter", 24.79)}

    ''' <summary>Smallest g on the slider, m/s².</summary>
    Public Const Minimum As Double = 0.0
    ''' <summary>Largest g on the slider, m/s².</summary>
    Public Const Maximum As Double = 100.0
End Class
