Option Strict On
Imports PhysicsEngine.Presentation

''' <summary>Which scene-file store the app uses.</summary>
Friend Module SceneStores
    ''' <summary>The store for physics-scene/1 files, or Nothing while this build has no scene-file support.</summary>
    Public Function Create() As ISceneStore
        Return Nothing
    End Function
End Module
