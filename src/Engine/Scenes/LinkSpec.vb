Option Strict On

Namespace Scenes
    ''' <summary>One link as read and checked from a scene file, before any world is built.</summary>
    Friend NotInheritable Class LinkSpec
        ''' <summary>0-based position in the file's "links" array.</summary>
        Friend Property Index As Integer
        Friend Property Kind As LinkKind
        Friend Property Id As String
        ''' <summary>End a: a movable body.</summary>
        Friend Property A As BodySpec
        ''' <summary>End b: a body, or Nothing when end b is the fixed point <see cref="Anchor"/>.</summary>
        Friend Property B As BodySpec
        ''' <summary>End b's fixed point, m (when <see cref="B"/> is Nothing).</summary>
        Friend Property Anchor As Vector
        ''' <summary>A rod's or string's length, or a spring's rest length, m.</summary>
        Friend Property Length As Double
        ''' <summary>N/m (springs).</summary>
        Friend Property Stiffness As Double
        ''' <summary>N·s/m (springs).</summary>
        Friend Property Damping As Double

        ''' <summary>Builds the model link between the bodies built from the specs (<paramref name="shapes"/>, in file order).</summary>
        Friend Function ToLink(shapes As IReadOnlyList(Of Shape)) As Link
            Dim bodyA = shapes(A.Index)
            If Kind = LinkKind.Spring Then
                If B Is Nothing Then Return Link.CreateSpring(bodyA, Anchor, Stiffness, Length, Damping, Id)
                Return Link.CreateSpring(bodyA, shapes(B.Index), Stiffness, Length, Damping, Id)
            End If
            If B Is Nothing Then Return Link.CreateTie(Kind, bodyA, Anchor, Length, Id)
            Return Link.CreateTie(Kind, bodyA, shapes(B.Index), Length, Id)
        End Function
    End Class
End Namespace
