Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' A menu that drops down from one of the window's buttons (Solver, Measure, Liquid, Scenes): made afresh in
''' the theme's colours each time it opens, kept on the screen, and, with --trace, saying where each item is
''' (the GUI tests click them there). What an item does is the presenter's.
''' </summary>
Friend MustInherit Class DropDownMenu
    Implements IDisposable

    Private ReadOnly _name As String
    Private _back As Color
    Private _fore As Color

    ''' <param name="kit">the window's services</param>
    ''' <param name="owner">the button the menu drops down from</param>
    ''' <param name="name">the menu's name in the trace ("solver" writes "solver menu shown 3")</param>
    Protected Sub New(kit As WindowKit, owner As Button, name As String)
        Me.Kit = kit
        Me.Owner = owner
        _name = name
        AddHandler Strip.Closed, Sub(s, e) Me.Kit.Emit(_name & " menu closed")
    End Sub

    ''' <summary>The window's services.</summary>
    Protected ReadOnly Property Kit As WindowKit

    ''' <summary>The button the menu drops down from.</summary>
    Protected ReadOnly Property Owner As Button

    ''' <summary>The menu itself.</summary>
    Protected ReadOnly Property Strip As New ContextMenuStrip()

    ''' <summary>The theme's panel colour, for items (set by <see cref="Begin"/>).</summary>
    Protected ReadOnly Property Back As Color
        Get
            Return _back
        End Get
    End Property

    ''' <summary>The theme's panel text colour, for items (set by <see cref="Begin"/>).</summary>
    Protected ReadOnly Property Fore As Color
        Get
            Return _fore
        End Get
    End Property

    ''' <summary>Empties the menu and gives it the theme's look, ready for this opening's items.</summary>
    Protected Sub Begin()
        Dim theme = Kit.Presenter.Theme
        Kit.Prepare(Strip, theme)
        _back = ScenePainter.Rgb(theme.Panel)
        _fore = ScenePainter.Rgb(theme.PanelText)
    End Sub

    ''' <summary>An item in the theme's colours that runs <paramref name="action"/> under the window's guard when clicked.</summary>
    Protected Function NewItem(text As String, tip As String, action As Action, Optional checked As Boolean = False) As ToolStripMenuItem
        Dim item As New ToolStripMenuItem(text) With {.BackColor = _back, .ForeColor = _fore, .ToolTipText = tip, .Checked = checked}
        AddHandler item.Click, Sub(s, e) Kit.Act(action)
        Return item
    End Function

    ''' <summary>
    ''' Shows the menu under its button, moved as far as it takes to stay on the screen. With --trace, writes
    ''' each item's place ("solver item 0 x y w h event", with its name from <paramref name="itemNames"/>
    ''' when given), the menu's bounds, and "solver menu shown n".
    ''' </summary>
    Protected Sub Drop(Optional itemNames As IReadOnlyList(Of String) = Nothing)
        Strip.Show(Kit.OnScreen(Owner, Strip.GetPreferredSize(Size.Empty)))
        If Kit.Trace Is Nothing Then Return
        For i = 0 To Strip.Items.Count - 1
            Dim b = Strip.Items(i).Bounds
            Dim at = Strip.PointToScreen(b.Location)
            Dim named = If(itemNames IsNot Nothing AndAlso i < itemNames.Count, " " & itemNames(i), "")
            Kit.Emit(_name & " item " & i & " " & at.X & " " & at.Y & " " & b.Width & " " & b.Height & named)
        Next
        Kit.TraceMenuBounds(_name & " menu", Strip)
        Kit.Emit(_name & " menu shown " & Strip.Items.Count)
    End Sub

    ''' <summary>Frees the menu.</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        Strip.Dispose()
        GC.SuppressFinalize(Me)
    End Sub
End Class
