Option Strict On

''' <summary>The sides of the container.</summary>
Public Enum WallSide
    None = 0
    Left
    Right
    Bottom
    Top
End Enum
