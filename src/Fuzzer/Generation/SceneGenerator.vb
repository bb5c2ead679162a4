Option Strict On

Namespace Generation
    ''' <summary>
    ''' Random scenes from a seed: the same seed and options give the same scene, bit for bit. A scene is
    ''' a world (centimetres to kilometres, g from 0 to 100 m/s², e from 0 to 1, walls mostly on) and a mix
    ''' of ingredients: obstacles first (so that balls can be put exactly on them), then up to three
    ''' structures (touching rows, piles, balls on tops and corners), then scattered balls for the rest of
    ''' the budget, then links. Every scene passes the scene reader's checks.
    ''' </summary>
    Friend Module SceneGenerator
        ''' <summary>Obstacles: fixed bodies placed first.</summary>
        Friend ReadOnly Obstacles As IReadOnlyList(Of Ingredient) = {
            New RectanglesIngredient(), New FixedCirclesIngredient(), New SegmentsIngredient(), New PolygonsIngredient()}

        ''' <summary>Structures: the hard starts (touching, resting, heaped).</summary>
        Friend ReadOnly Structures As IReadOnlyList(Of Ingredient) = {
            New TouchingPairIngredient(), New CradleIngredient(), New PileIngredient(), New StackIngredient(),
            New RestOnRectangleIngredient(), New RestOnCornerIngredient(), New RestOnFixedCircleIngredient(),
            New RestOnFloorIngredient(), New BoxesIngredient()}

        Private ReadOnly Scatter As New ScatterIngredient()
        Private ReadOnly LinkMaker As New LinksIngredient()

        ''' <summary>Every ingredient, for coverage reports.</summary>
        Friend ReadOnly Property All As IReadOnlyList(Of Ingredient) = Obstacles.Concat(Structures).Concat({CType(Scatter, Ingredient), LinkMaker}).ToList()

        ''' <summary>
        ''' The scene of <paramref name="seed"/>, with bodies of <paramref name="kinds"/> only and at most about
        ''' <paramref name="maxBodies"/> of them (obstacles come on top); a fraction <paramref name="rough"/> of the
        ''' scenes have friction, μk from 0.05 to 1 and μs up to 1.5 μk, drawn from a stream of their own so that a
        ''' seed's bodies are the same rough or not.
        ''' </summary>
        Friend Function Generate(seed As Long, kinds As BodyKinds, maxBodies As Integer, Optional rough As Double = 0) As SceneDraft
            If maxBodies < 1 Then Throw New ArgumentOutOfRangeException(NameOf(maxBodies), "at least one body")
            Dim rng As New SplitMix(seed)
            Dim world = DrawWorld(rng)
            Dim surfaces As New SplitMix(seed Xor &H5EEDF00DL)
            If surfaces.NextDouble() < rough Then
                world.Friction = surfaces.Uniform(0.05, 1)
                world.StaticFriction = world.Friction * surfaces.Uniform(1, 1.5)
            End If
            ' Half the scenes are small: failures shrink faster and small scenes run faster.
            Dim budget = If(rng.Chance(0.5), rng.Between(1, maxBodies), rng.Between(1, Math.Max(1, maxBodies \ 4)))
            Dim scene As New SceneBuilder(rng, world, kinds, budget)

            ' Obstacles do not count against the budget of movable bodies.
            Dim movableBudget = scene.Budget
            scene.Budget = Integer.MaxValue
            For Each ingredient In Obstacles
                If rng.Chance(0.5) AndAlso scene.Has(ingredient.Needs) Then Use(scene, ingredient)
            Next
            scene.Budget = movableBudget

            Dim available = Structures.Where(Function(i) scene.Has(i.Needs)).ToList()
            If available.Count > 0 Then
                Dim count = rng.Between(0, 3)
                For k = 1 To count
                    Use(scene, rng.Pick(available))
                Next
            End If
            If scene.Has(Scatter.Needs) AndAlso rng.Chance(0.8) Then Use(scene, Scatter)
            ' A scene where nothing can move tests nothing.
            If scene.Has(Scatter.Needs) AndAlso scene.Bodies.All(Function(b) b.IsFixed) Then
                scene.Budget = Math.Max(scene.Budget, 1)
                Use(scene, Scatter)
            End If
            If scene.Has(LinkMaker.Needs) AndAlso rng.Chance(0.6) Then Use(scene, LinkMaker)
            Return New SceneDraft(seed, world, scene.Bodies.ToList(), scene.Links.ToList(), scene.Used.ToList())
        End Function

        Private Sub Use(scene As SceneBuilder, ingredient As Ingredient)
            Dim before = scene.Bodies.Count + scene.Links.Count
            ingredient.Apply(scene)
            If scene.Bodies.Count + scene.Links.Count > before Then scene.Used.Add(ingredient.Name)
        End Sub

        ''' <summary>
        ''' Container: metres mostly, centimetres or kilometres one time in ten each. g: 0 (30%), 100 (15%),
        ''' 9.81 (15%) or anything between. e: 0 (20%), 1 (25%) or anything between. Walls on 80% of the time.
        ''' </summary>
        Private Function DrawWorld(rng As SplitMix) As WorldDraft
            Dim w As New WorldDraft()
            Dim size = rng.NextDouble()
            If size < 0.1 Then
                w.Width = rng.LogUniform(0.02, 0.3)
                w.Height = rng.LogUniform(0.02, 0.3)
            ElseIf size < 0.2 Then
                w.Width = rng.LogUniform(100, 3000)
                w.Height = rng.LogUniform(100, 3000)
            Else
                w.Width = rng.LogUniform(0.5, 10)
                w.Height = rng.LogUniform(0.5, 10)
            End If
            Dim g = rng.NextDouble()
            w.Gravity = If(g < 0.3, 0.0, If(g < 0.45, 100.0, If(g < 0.6, 9.81, rng.Uniform(0, 100))))
            Dim e = rng.NextDouble()
            w.Restitution = If(e < 0.2, 0.0, If(e < 0.45, 1.0, rng.NextDouble()))
            w.Walls = rng.Chance(0.8)
            Return w
        End Function
    End Module
End Namespace
