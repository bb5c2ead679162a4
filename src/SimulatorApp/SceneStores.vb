Option Strict On
Imports PhysicsEngine.Presentation

''' <summary>Which scene-file store the app uses.</summary>
Friend Module SceneStores
    ''' <summary>The store for physics-scene/1 files.</summary>
    Public Function Create() As ISceneStore
        Return New SceneFileStore()
    End Function
End Module
