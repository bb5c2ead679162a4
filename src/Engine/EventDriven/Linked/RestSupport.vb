Option Strict On

''' <summary>What a resting body in the linked event solver rests on: the container's floor or a side wall, a fixed body, or a movable body that itself rests level.</summary>
Friend Enum RestSupportKind As Byte
    ''' <summary>A wall of the container (<see cref="RestSupport.Index"/> is its <see cref="WallSide"/>).</summary>
    Wall
    ''' <summary>A fixed body (<see cref="RestSupport.Index"/> indexes the solver's fixed bodies).</summary>
    Fixed
    ''' <summary>A movable body resting level (<see cref="RestSupport.Index"/> indexes the solver's movable bodies).</summary>
    Body
End Enum

''' <summary>One support of a resting body: while it rests there, the contact with it is not searched (the body moves along its face, exactly).</summary>
Friend Structure RestSupport
    ''' <summary>What kind of thing it is.</summary>
    Friend Kind As RestSupportKind
    ''' <summary>Which one: a wall side, a fixed body's index or a movable body's index.</summary>
    Friend Index As Integer

    ''' <summary>The face's unit normal, from the support towards the body.</summary>
    Friend Normal As Vector

    ''' <summary>A support of the given kind and index, touched along <paramref name="normal"/>.</summary>
    Friend Sub New(kind As RestSupportKind, index As Integer, normal As Vector)
        Me.Kind = kind
        Me.Index = index
        Me.Normal = normal
    End Sub
End Structure
