Option Strict On

''' <summary>What a label on the canvas names.</summary>
Public Enum CanvasLabelKind
    ''' <summary>A body's id.</summary>
    Body
    ''' <summary>"CM": the centre of mass.</summary>
    CentreOfMass
    ''' <summary>"Σp": the total momentum.</summary>
    TotalMomentum
    ''' <summary>"Δp": an impulse at a collision.</summary>
    Impulse
    ''' <summary>A force of the free-body diagram, "N 19.6 N", at its arrow's tip.</summary>
    Force
    ''' <summary>ΣF beside m a, by the body whose forces are shown.</summary>
    ForceSum
End Enum

''' <summary>A label placed on the canvas: its text, what it names, and where it goes, px.</summary>
Public NotInheritable Class CanvasLabel
    Public Sub New(text As String, kind As CanvasLabelKind, box As LabelBox, inside As Boolean, body As Shape)
        Me.Text = text
        Me.Kind = kind
        Me.Box = box
        Me.Inside = inside
        Me.Body = body
    End Sub

    ''' <summary>The words.</summary>
    Public ReadOnly Property Text As String
    ''' <summary>What it names.</summary>
    Public ReadOnly Property Kind As CanvasLabelKind
    ''' <summary>Where it goes, px.</summary>
    Public ReadOnly Property Box As LabelBox
    ''' <summary>Whether it sits inside its own body (drawn in a light colour, no backing).</summary>
    Public ReadOnly Property Inside As Boolean
    ''' <summary>The body it names (a body's id, an impulse's), or Nothing.</summary>
    Public ReadOnly Property Body As Shape
End Class
