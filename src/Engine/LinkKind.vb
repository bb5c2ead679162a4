Option Strict On

''' <summary>What a <see cref="Link"/> is: how it pulls (and pushes) the two points it joins.</summary>
Public Enum LinkKind
    ''' <summary>Hooke's law along its line, k·(distance − rest length), plus damping times the rate of stretching.</summary>
    Spring
    ''' <summary>A rigid massless bar: the two points stay exactly its length apart.</summary>
    Rod
    ''' <summary>Inextensible: the points are never more than its length apart; slack when they are closer.</summary>
#Disable Warning CA1720 ' "string" is the physics word, and the scene format's name for it
    [String]
#Enable Warning CA1720
End Enum
