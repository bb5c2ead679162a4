Option Strict On

''' <summary>How a point on a taut link to a fixed anchor moves under gravity (see <see cref="Pendulum"/>).</summary>
Public Enum PendulumRegime
    ''' <summary>Not moving: at rest at the bottom, or balanced exactly at the top, or g = 0 with no speed.</summary>
    Rest
    ''' <summary>Swinging to and fro between ±θmax &lt; π.</summary>
    Libration
    ''' <summary>Exactly the energy to reach the top: it creeps towards it for ever (period +∞).</summary>
    Separatrix
    ''' <summary>Going over the top, round and round in one direction.</summary>
    Rotation
    ''' <summary>No gravity: uniform circular motion.</summary>
    Uniform
End Enum
