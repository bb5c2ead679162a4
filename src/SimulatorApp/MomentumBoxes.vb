Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The momentum views' block of the side panel: check boxes for the centre of mass, the total
''' momentum Σp, the momenta diagram, the impulses Δp, the path traces, and the container's walls.
''' What they do is the presenter's (its MomentumViews); the canvas draws them (ScenePainter.Momentum).
''' </summary>
Friend NotInheritable Class MomentumBoxes
    Implements IDisposable

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _showCentre As New ScaledCheckBox()
    Private ReadOnly _showTotal As New ScaledCheckBox()
    Private ReadOnly _showDiagram As New ScaledCheckBox()
    Private ReadOnly _showImpulses As New ScaledCheckBox()
    Private ReadOnly _showTraces As New ScaledCheckBox()
    Private ReadOnly _walls As New ScaledCheckBox()
    ''' <summary>True while the boxes are set to what the presenter says: their own change is not the teacher's.</summary>
    Private _showing As Boolean

    ''' <param name="panel">the side panel's content, where the boxes go</param>
    Public Sub New(kit As WindowKit, panel As Control)
        _kit = kit
        For Each b In {(_showCentre, MomentumCaptions.CentreOfMass, CType(Sub(v As Boolean) _kit.Presenter.SetShowCentreOfMass(v), Action(Of Boolean)), "The centre of mass of the moving bodies, with its velocity"),
                       (_showTotal, MomentumCaptions.TotalMomentum, CType(Sub(v As Boolean) _kit.Presenter.SetShowTotalMomentum(v), Action(Of Boolean)), "The total momentum Σp of the moving bodies, drawn from their centre of mass"),
                       (_showDiagram, MomentumCaptions.MomentaDiagram, CType(Sub(v As Boolean) _kit.Presenter.SetShowMomentaDiagram(v), Action(Of Boolean)), "Each body's momentum tip to tail, and their sum Σp (right of the container)"),
                       (_showImpulses, MomentumCaptions.Impulses, CType(Sub(v As Boolean) _kit.Presenter.SetShowImpulses(v), Action(Of Boolean)), "At each collision, the impulse Δp = m·(v after − v before) each body receives, for a second"),
                       (_showTraces, MomentumCaptions.Traces, CType(Sub(v As Boolean) _kit.Presenter.SetShowTraces(v), Action(Of Boolean)), "Where each body has been in the last 3 s, fading"),
                       (_walls, MomentumCaptions.Walls, CType(Sub(v As Boolean) _kit.Presenter.SetWalls(v), Action(Of Boolean)), "The sides of the box reflect the balls; without walls they fly out")}
            Dim box = b.Item1
            Dim action = b.Item3
            box.Text = b.Item2
            box.ScreenScale = kit.Dpi.Scale
            AddHandler box.CheckedChanged, Sub(s, e) If Not _showing Then _kit.Act(Sub() action(box.Checked))
            _kit.Tips.SetToolTip(box, b.Item4)
            panel.Controls.Add(box)
        Next
    End Sub

    ''' <summary>The block's rows, under the view options: three to a row when every caption fits, else two.</summary>
    Public Sub Arrange(rows As PanelRows, rowHeight As Integer, pairs As Boolean)
        rows.Gap()
        Dim boxes = {_showCentre, _showTotal, _showDiagram, _showImpulses, _showTraces, _walls}
        Dim shares = {0.38, 0.3, 0.32}
        Dim usable = rows.Width - 2 * _kit.S(6)
        Dim threes = pairs AndAlso Enumerable.Range(0, boxes.Length).All(Function(i) rows.TextFits(boxes(i), CInt(usable * shares(i Mod 3))))
        If threes Then
            rows.Row(rowHeight, (boxes(0), shares(0)), (boxes(1), shares(1)), (boxes(2), shares(2)))
            rows.Row(rowHeight, (boxes(3), shares(0)), (boxes(4), shares(1)), (boxes(5), shares(2)))
        Else
            rows.Row(rowHeight, (boxes(0), 0.5), (boxes(1), 0.5))
            rows.Row(rowHeight, (boxes(2), 0.5), (boxes(3), 0.5))
            rows.Row(rowHeight, (boxes(4), 0.5), (boxes(5), 0.5))
        End If
    End Sub

    ''' <summary>The boxes show the presenter's choices.</summary>
    Public Sub Show()
        Dim p = _kit.Presenter
        _showing = True
        Try
            _showCentre.Checked = p.ShowCentreOfMass
            _showTotal.Checked = p.ShowTotalMomentum
            _showDiagram.Checked = p.ShowMomentaDiagram
            _showImpulses.Checked = p.ShowImpulses
            _showTraces.Checked = p.ShowTraces
            _walls.Checked = p.HasWalls
        Finally
            _showing = False
        End Try
    End Sub

    ''' <summary>The block's controls, by the names the --trace layout gives them.</summary>
    Public Function Controls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("centre-of-mass", CType(_showCentre, Control)), ("total-momentum", CType(_showTotal, Control)),
                ("momenta-diagram", CType(_showDiagram, Control)), ("impulses", CType(_showImpulses, Control)),
                ("traces", CType(_showTraces, Control)), ("walls", CType(_walls, Control))}
    End Function

    ''' <summary>Its controls (the window disposes them too, with the panel; a second time does nothing).</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        _showCentre.Dispose()
        _showTotal.Dispose()
        _showDiagram.Dispose()
        _showImpulses.Dispose()
        _showTraces.Dispose()
        _walls.Dispose()
    End Sub
End Class
