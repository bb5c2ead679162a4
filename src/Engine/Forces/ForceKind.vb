Option Strict On

''' <summary>What kind of force a <see cref="BodyForce"/> is, as a free-body diagram names it.</summary>
Public Enum ForceKind
    ''' <summary>Gravity: m g downwards.</summary>
    Weight
    ''' <summary>A contact's push, square to the surfaces.</summary>
    Normal
    ''' <summary>A contact's push along the surfaces: static (sticking) or kinetic (sliding).</summary>
    Friction
    ''' <summary>A rod's or a taut string's pull (a rod may push).</summary>
    Tension
    ''' <summary>A spring's pull or push.</summary>
    Spring
    ''' <summary>Air and liquid resistance, against the velocity.</summary>
    Drag
    ''' <summary>A liquid's upthrust.</summary>
    Buoyancy
End Enum
