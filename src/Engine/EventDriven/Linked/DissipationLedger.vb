Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' Where the linked event solver counts the energy it takes out of the world (<see cref="World.Dissipated"/>):
''' the drag of a motion that knows its own (<see cref="IDissipatingMotion"/>: a closed form, or the integral
''' carried with the motion), the damping of springs and the friction of sliding contacts (from the energy the
''' group's motion has lost since it started: between events nothing else takes any), and the kinetic energy an inelastic blow or a string
''' snapping taut takes. Each motion is credited up to a time once: when an advance ends (the motion goes on)
''' and when the motion is replaced.
''' </summary>
Friend NotInheritable Class DissipationLedger
    ''' <summary>What a motion has been credited with so far (J), and for a damped group its energy at the start (J).</summary>
    Private NotInheritable Class Account
        Friend Credited As Double
        Friend StartEnergy As Double
    End Class

    Private ReadOnly _accounts As New ConditionalWeakTable(Of LinkedMotion, Account)

    ''' <summary>Group <paramref name="group"/>'s motion has just started, from its bodies' states now.</summary>
    Friend Sub Started(group As LinkedGroup, world As World)
        Dim m = group.Motion
        If m Is Nothing Then Return
        Dim account As New Account()
        If Not TypeOf m Is IDissipatingMotion Then
            If Not Damped(group) AndAlso Not Forced(group, world) AndAlso Not Rubbing(m) Then Return
            account.StartEnergy = Energy(group, world, m.StartTime)
        End If
        _accounts.Remove(m)
        _accounts.Add(m, account)
    End Sub

    ''' <summary>Credits group <paramref name="group"/>'s motion with what it has taken up to <paramref name="time"/> (s).</summary>
    Friend Sub Settle(group As LinkedGroup, world As World, time As Double)
        Dim m = group.Motion
        If m Is Nothing Then Return
        Dim account As Account = Nothing
        If Not _accounts.TryGetValue(m, account) Then Return
        Dim dissipating = TryCast(m, IDissipatingMotion)
        Dim taken = If(dissipating IsNot Nothing, dissipating.Dissipated(time), account.StartEnergy - Energy(group, world, time))
        If taken > account.Credited Then
            world.Dissipate(taken - account.Credited)
            account.Credited = taken
        End If
    End Sub

    ''' <summary>Σ ½ m v² of the bodies as written to them now, J.</summary>
    Friend Shared Function Kinetic(bodies As Shape()) As Double
        Dim sum = 0.0
        For Each b In bodies
            sum += b.KineticEnergy
        Next
        Return sum
    End Function

    ''' <summary>A blow (a collision, a string snapping taut) has acted: what it took from the bodies' kinetic energy, <paramref name="before"/> (J) less now.</summary>
    Friend Shared Sub Blow(world As World, before As Double, bodies As Shape())
        If world.Restitution < 1 Then world.Dissipate(before - Kinetic(bodies))
    End Sub

    ''' <summary>Whether drag or buoyancy acts on a body of the group (linked, so integrated by the springs' or the chains' motion).</summary>
    Private Shared Function Forced(group As LinkedGroup, world As World) As Boolean
        If Not world.HasDragOrLiquids Then Return False
        Dim forces As New ForceField(world)
        Return group.Bodies.Any(Function(b) forces.Acts(b))
    End Function

    ''' <summary>Whether a contact the motion holds slides with friction (its work is taken out as the group goes).</summary>
    Private Shared Function Rubbing(m As LinkedMotion) As Boolean
        Return m.HeldContacts.Any(Function(c) c.Sliding <> 0)
    End Function

    ''' <summary>Whether a spring of the group has damping.</summary>
    Private Shared Function Damped(group As LinkedGroup) As Boolean
        For Each l In group.Links
            If l.Kind = LinkKind.Spring AndAlso l.Damping > 0 Then Return True
        Next
        Return False
    End Function

    ''' <summary>
    ''' The group's mechanical energy on its motion at <paramref name="time"/> (s), J: ½ m v² + m g y of each body
    ''' (at its centre of mass), buoyancy's potential in each liquid, and ½ k (d − L)² of each spring, read from the
    ''' motion itself, so that a blow already applied to the bodies at that instant is not counted twice.
    ''' </summary>
    Private Shared Function Energy(group As LinkedGroup, world As World, time As Double) As Double
        Dim m = group.Motion
        Dim centres(m.Bodies.Length - 1) As Vector
        Dim sum = 0.0
        For k = 0 To m.Bodies.Length - 1
            Dim v As Vector
            m.StateAt(time, k, centres(k), v)
            Dim body = m.Bodies(k)
            sum += 0.5 * body.Mass * v.LengthSquared + body.Mass * world.Gravity * centres(k).Y
            For Each liquid In world.Liquids
                Dim part = SubmergedArea.Inside(body.Outline, centres(k) - body.Outline.Centroid, liquid.Min, liquid.Max)
                If part.Area > 0 Then sum += Buoyancy.Potential(liquid.Density, world.Gravity, liquid.Surface, part)
            Next
        Next
        For Each l In group.Links
            If l.Kind <> LinkKind.Spring Then Continue For
            Dim a = EndOf(m, centres, l.A)
            Dim b = If(l.B Is Nothing, l.Anchor, EndOf(m, centres, l.B))
            Dim extension = (b - a).Length - l.Length
            sum += 0.5 * l.Stiffness * extension * extension
        Next
        Return sum
    End Function

    Private Shared Function EndOf(m As LinkedMotion, centres As Vector(), body As Shape) As Vector
        Dim k = Array.IndexOf(m.Bodies, body)
        If k >= 0 Then Return centres(k)
        Return body.CentreOfMass
    End Function
End Class
