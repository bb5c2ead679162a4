Option Strict On

''' <summary>
''' Bodies joined by links, directly or through each other (a body with no links is a group of its own),
''' with the closed form that moves them now.
''' </summary>
Friend NotInheritable Class LinkedGroup
    Friend Sub New(bodies As List(Of Shape), links As List(Of Link))
        Me.Bodies = bodies
        Me.Links = links
    End Sub

    ''' <summary>The group's bodies.</summary>
    Friend ReadOnly Property Bodies As List(Of Shape)

    ''' <summary>The links among them and to fixed points.</summary>
    Friend ReadOnly Property Links As List(Of Link)

    ''' <summary>How the group moves from <see cref="LinkedMotion.StartTime"/> on.</summary>
    Friend Property Motion As LinkedMotion
End Class
