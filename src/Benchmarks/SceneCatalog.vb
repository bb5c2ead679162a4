Option Strict On

''' <summary>The benchmark's scenes by name.</summary>
Friend Module SceneCatalog
    ''' <summary>The scene called <paramref name="name"/>, sized for the run mode.</summary>
    Public Function Create(name As String, options As BenchmarkOptions) As IBenchScene
        If options Is Nothing Then Throw New ArgumentNullException(NameOf(options))
        Select Case name
            Case "bouncing-apex" : Return New BouncingApexScene()
            Case "bouncing-rest" : Return New BouncingRestScene()
            Case "projectile" : Return New ProjectileScene()
            Case "oblique-hit" : Return New ObliqueHitScene()
            Case "cradle" : Return New CradleScene()
            Case "gas-energy" : Return New GasEnergyScene(100, options.GasSeconds)
            Case "pile" : Return New PileScene()
            Case "ramp-slide" : Return New RampSlideScene()
            Case "box-drop" : Return New BoxDropScene()
            Case BoxPileScene.WideName : Return New BoxPileScene(BoxPileScene.WideName, 200, 10.0, 4.0)
            Case BoxPileScene.DeepName : Return New BoxPileScene(BoxPileScene.DeepName, 200, 3.0, 8.0)
            Case "pendulum" : Return New PendulumScene()
            Case "spring" : Return New SpringScene()
            Case "rope" : Return New RopeScene()
            Case "cradle-strings" : Return New CradleStringsScene()
            Case "galton" : Return New GaltonScene()
            Case "drag-projectile" : Return New DragProjectileScene()
            Case "tanh-fall" : Return New TanhFallScene()
            Case "floating-box" : Return New FloatingBoxScene()
            ' 0.1 s: the event solver's first 0.1 s of it takes about 14 s, so the run with the error checks
            ' and a timed run both fit the 30 s budget of a case (0.2 s took 28 to 30 s, and a busy
            ' machine left the row without a result).
            Case "mixed" : Return New MixedScene(If(options.Quick, 0.02, 0.1))
            Case Else : Throw New ArgumentException("unknown scene '" & name & "'", NameOf(name))
        End Select
    End Function
End Module
