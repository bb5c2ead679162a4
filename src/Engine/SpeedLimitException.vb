Option Strict On

''' <summary>
''' A movable body moves faster than <see cref="World.MaxSpeed"/>: no solver can give a meaningful
''' answer, because the square of its speed (kinetic energy, the contact-time quadratics) would
''' overflow double precision. The world is left as it was before the advance.
''' </summary>
Public NotInheritable Class SpeedLimitException
    Inherits InvalidOperationException

    ''' <summary>The body that is too fast.</summary>
    Public ReadOnly Property Body As Shape

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

    Public Sub New(body As Shape, speed As Double)
        MyBase.New(Describe(body, speed))
        Me.Body = body
        Me.Speed = speed
    End Sub

    Private Shared Function Describe(body As Shape, speed As Double) As String
        Dim kind = If(body Is Nothing, "body", body.KindName)
        Dim name = If(String.IsNullOrEmpty(body?.Id), "a " & kind, kind & " '" & body.Id & "'")
        Dim inv = Globalization.CultureInfo.InvariantCulture
        Return name & " moves at " & speed.ToString("G3", inv) & " m/s, faster than the " &
               World.MaxSpeed.ToString("G3", inv) & " m/s the simulation can handle (beyond that, the square of a speed overflows)"
    End Function
End Class
