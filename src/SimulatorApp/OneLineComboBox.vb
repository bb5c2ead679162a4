Option Strict On
Imports System.Drawing
Imports System.Windows.Forms

''' <summary>
''' A drop-down list as tall as the layout makes it (a line of text and a margin), its items as tall as
''' a line of their text, each drawn in the middle of its row. Mono makes a drop-down list as tall as the
''' font height it reports plus 8 px, whatever it is given, and under a desktop's Xft.dpi that height is
''' about twice the text drawn: at 192 dpi the box stood twice as tall as the text boxes beside it. It
''' stays a ComboBox: the keyboard, the list and SelectedIndexChanged work as before.
''' </summary>
Friend NotInheritable Class OneLineComboBox
    Inherits ComboBox

    Public Sub New()
        DropDownStyle = ComboBoxStyle.DropDownList
        DrawMode = DrawMode.OwnerDrawFixed
    End Sub

    ''' <summary>
    ''' Takes the bounds it is given. Mono snaps the height of a drop-down list to its own when the height
    ''' is named among the bounds set; set without naming it, it keeps what it is given (Windows sizes the
    ''' box from <see cref="ComboBox.ItemHeight"/> either way).
    ''' </summary>
    Protected Overrides Sub SetBoundsCore(x As Integer, y As Integer, width As Integer, height As Integer, specified As BoundsSpecified)
        MyBase.SetBoundsCore(x, y, width, height, BoundsSpecified.None)
    End Sub

    ''' <summary>An item (or the chosen one, in the box) in the control's colours and font, in the middle of its row.</summary>
    Protected Overrides Sub OnDrawItem(e As DrawItemEventArgs)
        If e Is Nothing Then Return
        e.DrawBackground()
        If e.Index >= 0 AndAlso e.Index < Items.Count Then
            Dim ink = If(Enabled, e.ForeColor, SystemColors.GrayText)
            ' The chosen item in the box is centred in the box as it is (Mono's area for it is as tall as the box it would have made).
            Dim area = e.Bounds
            If (e.State And DrawItemState.ComboBoxEdit) = DrawItemState.ComboBoxEdit Then area = New Drawing.Rectangle(area.X, 0, area.Width, ClientSize.Height)
            TextRenderer.DrawText(e.Graphics, GetItemText(Items(e.Index)), Font, area, ink,
                                  TextFormatFlags.VerticalCenter Or TextFormatFlags.Left Or TextFormatFlags.NoPrefix Or TextFormatFlags.SingleLine Or TextFormatFlags.EndEllipsis)
        End If
        e.DrawFocusRectangle()
        MyBase.OnDrawItem(e)
    End Sub
End Class
