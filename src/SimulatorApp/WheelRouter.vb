Option Strict On
Imports System.Drawing
Imports System.Windows.Forms

''' <summary>
''' Sends the mouse wheel to what is under the pointer. Windows sends it to the window under the
''' pointer, but Mono sends it to the control with the keyboard focus: a wheel turned over the side
''' panel while a text box elsewhere has the focus scrolled nothing. This filter sees every wheel
''' message first and hands it to the first registered area that holds the pointer.
''' </summary>
Friend NotInheritable Class WheelRouter
    Implements IMessageFilter

    Private Const WmMouseWheel As Integer = &H20A
    Private ReadOnly _areas As New List(Of (Target As Control, Handler As Action(Of Integer, Point)))

    ''' <summary>
    ''' Turns of the wheel over <paramref name="target"/> go to <paramref name="handler"/>: the turn
    ''' (+120 a notch away from the user, −120 towards) and the pointer in the target's coordinates.
    ''' </summary>
    Public Sub Add(target As Control, handler As Action(Of Integer, Point))
        _areas.Add((target, handler))
    End Sub

    Public Function PreFilterMessage(ByRef m As Message) As Boolean Implements IMessageFilter.PreFilterMessage
        If m.Msg <> WmMouseWheel Then Return False
        ' The turn is the high word of wParam, a signed 16-bit number.
        Dim delta = CInt((m.WParam.ToInt64() >> 16) And &HFFFF)
        If delta >= &H8000 Then delta -= &H10000
        Dim screen = Control.MousePosition
        For Each area In _areas
            Dim t = area.Target
            If t.IsDisposed OrElse Not t.Visible OrElse Not t.IsHandleCreated Then Continue For
            Dim local = t.PointToClient(screen)
            If t.ClientRectangle.Contains(local) Then
                area.Handler(delta, local)
                Return True
            End If
        Next
        Return False
    End Function
End Class
