Option Strict On

''' <summary>
''' A movable circle moves faster than <see cref="World.MaxSpeed"/>: no solver can give a meaningful
''' answer, because the square of its speed (kinetic energy, the contact-time quadratics) would
''' overflow double precision. The world is left as it was before the advance.
''' </summary>
Public NotInheritable Class SpeedLimitException
    Inherits InvalidOperationException

    ''' <summary>The circle that is too fast.</summary>
    Public ReadOnly Property Circle As Circle

    ''' <summary>Its speed, m/s.</summary>
    Public ReadOnly Property Speed As Double

    Public Sub New()
    End Sub

    Public Sub New(message As String)
        MyBase.New(message)
    End Sub

    Public Sub New(message As String, innerException As Exception)
        MyBase.New(message, innerException)
    End Sub

    Public Sub New(circle As Circle, speed As Double)
        MyBase.New(Describe(circle, speed))
        Me.Circle = circle
        Me.Speed = speed
    End Sub

    Private Shared Function Describe(circle As Circle, speed As Double) As String
        Dim name = If(String.IsNullOrEmpty(circle?.Id), "a circle", "circle '" & circle.Id & "'")
        Dim inv = Globalization.CultureInfo.InvariantCulture
        Return name & " moves at " & speed.ToString("G3", inv) & " m/s, faster than the " &
               World.MaxSpeed.ToString("G3", inv) & " m/s the simulation can handle (beyond that, the square of a speed overflows)"
    End Function
End Class
