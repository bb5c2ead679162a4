Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' The momentum views' block of the side panel: check boxes for the centre of mass, the total
' momentum Σp, the momenta diagram, the impulses Δp, the path traces, and the container's walls.
' What they do is the presenter's (SimulationPresenter.Momentum); the canvas draws them (ScenePainter.Momentum).
Partial Friend NotInheritable Class MainForm
    Private ReadOnly _showCentre As New ScaledCheckBox()
    Private ReadOnly _showTotal As New ScaledCheckBox()
    Private ReadOnly _showDiagram As New ScaledCheckBox()
    Private ReadOnly _showImpulses As New ScaledCheckBox()
    Private ReadOnly _showTraces As New ScaledCheckBox()
    Private ReadOnly _walls As New ScaledCheckBox()

    Private Sub BuildMomentumControls()
        AddCheck(_showCentre, MomentumCaptions.CentreOfMass, Sub() _presenter.SetShowCentreOfMass(_showCentre.Checked))
        AddCheck(_showTotal, MomentumCaptions.TotalMomentum, Sub() _presenter.SetShowTotalMomentum(_showTotal.Checked))
        AddCheck(_showDiagram, MomentumCaptions.MomentaDiagram, Sub() _presenter.SetShowMomentaDiagram(_showDiagram.Checked))
        AddCheck(_showImpulses, MomentumCaptions.Impulses, Sub() _presenter.SetShowImpulses(_showImpulses.Checked))
        AddCheck(_showTraces, MomentumCaptions.Traces, Sub() _presenter.SetShowTraces(_showTraces.Checked))
        AddCheck(_walls, MomentumCaptions.Walls, Sub() _presenter.SetWalls(_walls.Checked))
        _tips.SetToolTip(_showCentre, "The centre of mass of the moving bodies, with its velocity")
        _tips.SetToolTip(_showTotal, "The total momentum Σp of the moving bodies, drawn from their centre of mass")
        _tips.SetToolTip(_showDiagram, "Each body's momentum tip to tail, and their sum Σp (top right of the canvas)")
        _tips.SetToolTip(_showImpulses, "At each collision, the impulse Δp = m·(v after − v before) each body receives, for a second")
        _tips.SetToolTip(_showTraces, "Where each body has been in the last 3 s, fading")
        _tips.SetToolTip(_walls, "The sides of the box reflect the balls; without walls they fly out")
    End Sub

    ''' <summary>The block's rows, under the view options: three to a row when every caption fits, else two.</summary>
    Private Sub ArrangeMomentumControls(rowHeight As Integer, pairs As Boolean)
        Gap()
        Dim boxes = {_showCentre, _showTotal, _showDiagram, _showImpulses, _showTraces, _walls}
        Dim shares = {0.38, 0.3, 0.32}
        Dim usable = _rowWidth - 2 * S(6)
        Dim threes = pairs AndAlso Enumerable.Range(0, boxes.Length).All(Function(i) TextFits(boxes(i), CInt(usable * shares(i Mod 3))))
        If threes Then
            Row(rowHeight, (boxes(0), shares(0)), (boxes(1), shares(1)), (boxes(2), shares(2)))
            Row(rowHeight, (boxes(3), shares(0)), (boxes(4), shares(1)), (boxes(5), shares(2)))
        Else
            Row(rowHeight, (boxes(0), 0.5), (boxes(1), 0.5))
            Row(rowHeight, (boxes(2), 0.5), (boxes(3), 0.5))
            Row(rowHeight, (boxes(4), 0.5), (boxes(5), 0.5))
        End If
    End Sub

    ''' <summary>The boxes show the presenter's choices (called from ShowSettings).</summary>
    Private Sub ShowMomentumSettings()
        _showCentre.Checked = _presenter.ShowCentreOfMass
        _showTotal.Checked = _presenter.ShowTotalMomentum
        _showDiagram.Checked = _presenter.ShowMomentaDiagram
        _showImpulses.Checked = _presenter.ShowImpulses
        _showTraces.Checked = _presenter.ShowTraces
        _walls.Checked = _presenter.HasWalls
    End Sub

    ''' <summary>The block's controls, by the names the --trace layout gives them.</summary>
    Private Function MomentumControls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("centre-of-mass", CType(_showCentre, Control)), ("total-momentum", CType(_showTotal, Control)),
                ("momenta-diagram", CType(_showDiagram, Control)), ("impulses", CType(_showImpulses, Control)),
                ("traces", CType(_showTraces, Control)), ("walls", CType(_walls, Control))}
    End Function
End Class
