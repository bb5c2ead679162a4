Option Strict On

''' <summary>
''' Reads and writes scene files (physics-scene/1). The presenter opens and saves through this, so it
''' does not depend on how files are parsed; errors are exceptions whose Message is one line.
''' </summary>
Public Interface ISceneStore
    ''' <summary>Reads the scene at <paramref name="path"/>; throws with a one-line message when it is not valid.</summary>
    Function Load(path As String) As World

    ''' <summary>Writes <paramref name="world"/> to <paramref name="path"/> (whole file or nothing).</summary>
    Sub Save(world As World, path As String)
End Interface
