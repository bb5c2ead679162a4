Option Strict On

Namespace Generation
    ''' <summary>
    ''' The scene reader's rules for where a body may start: a movable body wholly inside a walled container,
    ''' and no two bodies that collide with each other (anything but two fixed ones) overlapping by more
    ''' than 1e-9 m (touching is allowed). Circles and axis-aligned rectangles are checked exactly; a
    ''' polygon, and a box or rectangle against a segment or polygon, by a circle that holds the body,
    ''' which only ever refuses more.
    ''' </summary>
    Friend Module Placement
        ''' <summary>The overlap the reader allows, m.</summary>
        Friend Const Tolerance As Double = 0.000000001

        ''' <summary>True when <paramref name="candidate"/> may join <paramref name="placed"/> in <paramref name="world"/>.</summary>
        Friend Function Fits(world As WorldDraft, placed As IEnumerable(Of BodyDraft), candidate As BodyDraft) As Boolean
            If Not IsFinite(candidate) Then Return False
            If world.Walls AndAlso Not candidate.IsFixed AndAlso Not Inside(world, candidate) Then Return False
            For Each other In placed
                If candidate.IsFixed AndAlso other.IsFixed AndAlso Not BothCircles(candidate, other) Then Continue For
                If Depth(candidate, other) > Tolerance Then Return False
            Next
            Return True
        End Function

        ' The format lets fixed bodies overlap each other, but the scene reader's overlap check tests every
        ' pair of circles, fixed or not, and refuses two fixed circles that overlap; until it follows the
        ' format, generated scenes keep fixed circles apart.
        Private Function BothCircles(a As BodyDraft, b As BodyDraft) As Boolean
            Return a.Shape = DraftShape.Circle AndAlso b.Shape = DraftShape.Circle
        End Function

        ''' <summary>Whether a movable body lies wholly inside the container (to the reader's 1e-9 m).</summary>
        Friend Function Inside(world As WorldDraft, b As BodyDraft) As Boolean
            Dim lo = New Vector(-Tolerance, -Tolerance)
            Dim hi = New Vector(world.Width + Tolerance, world.Height + Tolerance)
            Select Case b.Shape
                Case DraftShape.Circle
                    Return b.Position.X - b.Radius >= lo.X AndAlso b.Position.X + b.Radius <= hi.X AndAlso
                        b.Position.Y - b.Radius >= lo.Y AndAlso b.Position.Y + b.Radius <= hi.Y
                Case DraftShape.Rectangle
                    Return b.Position.X >= lo.X AndAlso b.Position.Y >= lo.Y AndAlso b.Corner.X <= hi.X AndAlso b.Corner.Y <= hi.Y
                Case DraftShape.Polygon
                    Return b.Vertices.All(Function(v) v.X >= lo.X AndAlso v.Y >= lo.Y AndAlso v.X <= hi.X AndAlso v.Y <= hi.Y)
                Case Else
                    Return True ' segments are fixed
            End Select
        End Function

        ''' <summary>How deep two bodies overlap, m (≤ 0 when apart or touching).</summary>
        Friend Function Depth(a As BodyDraft, b As BodyDraft) As Double
            If a.Shape = DraftShape.Polygon Then Return Depth(a.Bound(), b)
            If b.Shape = DraftShape.Polygon Then Return Depth(a, b.Bound())
            If a.Shape = DraftShape.Segment AndAlso b.Shape = DraftShape.Segment Then Return 0 ' both fixed
            If a.Shape = DraftShape.Segment Then Return Depth(b, a)
            Select Case a.Shape
                Case DraftShape.Circle
                    Select Case b.Shape
                        Case DraftShape.Circle
                            Return a.Radius + b.Radius - Vector.Hypot(a.Position.X - b.Position.X, a.Position.Y - b.Position.Y)
                        Case DraftShape.Rectangle
                            Return Geometry.CircleBoxDepth(a.Position.X, a.Position.Y, a.Radius, b.Position.X, b.Position.Y, b.Corner.X, b.Corner.Y)
                        Case Else
                            Return a.Radius - Geometry.PointSegmentDistance(a.Position, b.Position, b.EndPoint)
                    End Select
                Case Else ' a rectangle
                    Select Case b.Shape
                        Case DraftShape.Circle
                            Return Depth(b, a)
                        Case DraftShape.Rectangle
                            Return Collider.BoxBoxDepth(a.Position, a.Corner, b.Position, b.Corner)
                        Case Else
                            Return Depth(a.Bound(), b)
                    End Select
            End Select
        End Function

        Private Function IsFinite(b As BodyDraft) As Boolean
            Dim numbers = {b.Position.X, b.Position.Y, b.Radius, b.Width, b.Height, b.EndPoint.X, b.EndPoint.Y, b.Mass, b.Velocity.X, b.Velocity.Y}
            If numbers.Any(Function(v) Double.IsNaN(v) OrElse Double.IsInfinity(v)) Then Return False
            Return b.Vertices Is Nothing OrElse b.Vertices.All(Function(v) v.IsFinite)
        End Function
    End Module
End Namespace
