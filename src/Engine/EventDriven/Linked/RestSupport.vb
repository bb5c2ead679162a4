Option Strict On

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
