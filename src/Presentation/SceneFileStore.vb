Option Strict On
Imports PhysicsEngine.Scenes

''' <summary>Scene files on disk through the engine's <see cref="SceneFile"/> (physics-scene/1; saving is atomic).</summary>
Public NotInheritable Class SceneFileStore
    Implements ISceneStore

    ''' <summary>Reads a scene file; a bad one throws <see cref="SceneFormatException"/> with a one-line message.</summary>
    Public Function Load(path As String) As World Implements ISceneStore.Load
        Return SceneFile.LoadFile(path)
    End Function

    ''' <summary>Writes the scene, whole or not at all.</summary>
    Public Sub Save(world As World, path As String) Implements ISceneStore.Save
        SceneFile.SaveFile(world, path)
    End Sub
End Class
