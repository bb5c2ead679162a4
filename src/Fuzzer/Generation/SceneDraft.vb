Option Strict On

Namespace Generation
    ''' <summary>A generated scene: its seed, world, bodies, links and the ingredients that made it.</summary>
    Friend NotInheritable Class SceneDraft
        Friend Sub New(seed As Long, world As WorldDraft, bodies As IReadOnlyList(Of BodyDraft), links As IReadOnlyList(Of LinkDraft), ingredients As IReadOnlyList(Of String))
            Me.Seed = seed
            Me.World = world
            Me.Bodies = bodies
            Me.Links = links
            Me.Ingredients = ingredients
        End Sub

        Friend ReadOnly Property Seed As Long
        Friend ReadOnly Property World As WorldDraft
        Friend ReadOnly Property Bodies As IReadOnlyList(Of BodyDraft)
        Friend ReadOnly Property Links As IReadOnlyList(Of LinkDraft)
        ''' <summary>Ingredient names in the order they were applied.</summary>
        Friend ReadOnly Property Ingredients As IReadOnlyList(Of String)

        ''' <summary>The scene as a document of pieces (what runs and what shrinking cuts).</summary>
        Friend Function ToDoc() As SceneDoc
            Dim bodies = Me.Bodies.Select(Function(b) New SceneItem(b.Id, b.ToJson())).ToList()
            Dim links = Me.Links.Select(Function(l) New SceneItem(l.Id, l.ToJson(), If(l.B Is Nothing, {l.A}, {l.A, l.B}))).ToList()
            Return New SceneDoc(World.ToJson(), bodies, links)
        End Function

        ''' <summary>The physics-scene/1 text.</summary>
        Friend Function ToText() As String
            Return ToDoc().ToText()
        End Function

        ''' <summary>The fastest body at the start, m/s.</summary>
        Friend Function TopSpeed() As Double
            Return If(Bodies.Count = 0, 0.0, Bodies.Max(Function(b) If(b.IsFixed, 0.0, b.Velocity.Length)))
        End Function

        ''' <summary>The smallest movable circle's radius, m (∞ when there is none).</summary>
        Friend Function SmallestRadius() As Double
            Dim r = Double.PositiveInfinity
            For Each b In Bodies
                If b.Shape = DraftShape.Circle AndAlso Not b.IsFixed Then r = Math.Min(r, b.Radius)
            Next
            Return r
        End Function
    End Class
End Namespace
