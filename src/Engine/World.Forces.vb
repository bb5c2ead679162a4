Option Strict On

' Friction, air and liquids (docs/forces.md): the world's own coefficients, its liquid regions, and the
' energy the dissipative forces and inelastic contacts have taken out of it.
Partial Public NotInheritable Class World
    Private ReadOnly _liquids As New List(Of Liquid)
    Private _friction As Double
    Private _staticFriction As Double?
    Private _airDensity As Double
    Private _dissipated As Double

    ''' <summary>
    ''' μk, the coefficient of kinetic (sliding) friction of every surface that has none of its own: walls,
    ''' fixed bodies, boxes and polygons (≥ 0; 0 by default: ice). Circles take no friction.
    ''' </summary>
    Public Property Friction As Double
        Get
            Return _friction
        End Get
        Set(value As Double)
            Shape.CheckCoefficient(value, NameOf(Friction))
            If _staticFriction.HasValue AndAlso _staticFriction.Value < value Then Throw New ArgumentOutOfRangeException(NameOf(Friction), "friction must not be above static friction (" & _staticFriction.Value.ToString(Globalization.CultureInfo.InvariantCulture) & ")")
            _friction = value
            _solver?.Invalidate(Nothing)
        End Set
    End Property

    ''' <summary>μs of every surface that has none of its own, or Nothing for the same as <see cref="Friction"/>; never below it.</summary>
    Public Property StaticFriction As Double?
        Get
            Return _staticFriction
        End Get
        Set(value As Double?)
            If value.HasValue Then
                Shape.CheckCoefficient(value.Value, NameOf(StaticFriction))
                If value.Value < _friction Then Throw New ArgumentOutOfRangeException(NameOf(StaticFriction), "static friction must be at least friction (" & _friction.ToString(Globalization.CultureInfo.InvariantCulture) & ")")
            End If
            _staticFriction = value
            _solver?.Invalidate(Nothing)
        End Set
    End Property

    ''' <summary>ρ of the air, kg/m² (areal, ≥ 0; 0 by default: no air resistance). Quadratic drag acts on bodies with a drag coefficient.</summary>
    Public Property AirDensity As Double
        Get
            Return _airDensity
        End Get
        Set(value As Double)
            Shape.CheckCoefficient(value, NameOf(AirDensity))
            _airDensity = value
            _solver?.Invalidate(Nothing)
        End Set
    End Property

    ''' <summary>The liquid regions, in the order added.</summary>
    Public ReadOnly Property Liquids As IReadOnlyList(Of Liquid)
        Get
            Return _liquids
        End Get
    End Property

    ''' <summary>
    ''' Adds a liquid region. An empty id is given the next free number (ids are shared with bodies). Refused
    ''' (ArgumentException) when it overlaps a liquid already here: which density would a body there feel?
    ''' </summary>
    Public Sub Add(liquid As Liquid)
        If liquid Is Nothing Then Throw New ArgumentNullException(NameOf(liquid))
        If _liquids.Contains(liquid) Then Throw New ArgumentException("this liquid is already in the world", NameOf(liquid))
        For Each other In _liquids
            If other.Overlaps(liquid) Then Throw New ArgumentException("liquids may not overlap: this one overlaps '" & other.Id & "'", NameOf(liquid))
        Next
        If String.IsNullOrEmpty(liquid.Id) Then
            Do
                liquid.Id = _nextId.ToString(Globalization.CultureInfo.InvariantCulture)
                _nextId += 1
            Loop While _ids.Contains(liquid.Id)
        ElseIf _ids.Contains(liquid.Id) Then
            Throw New ArgumentException("id '" & liquid.Id & "' is already used", NameOf(liquid))
        End If
        _ids.Add(liquid.Id)
        _liquids.Add(liquid)
        _solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>Removes a liquid region; returns False when it was not in the world.</summary>
    Public Function Remove(liquid As Liquid) As Boolean
        If liquid Is Nothing OrElse Not _liquids.Remove(liquid) Then Return False
        _ids.Remove(liquid.Id)
        _solver?.Invalidate(Nothing)
        return True
    End Function

    ''' <summary>The liquid with this id, or Nothing.</summary>
    Public Function FindLiquid(id As String) As Liquid
        For Each l In _liquids
            If String.Equals(l.Id, id, StringComparison.Ordinal) Then Return l
        Next
        Return Nothing
    End Function

    ''' <summary>Sets a body's own friction (μk, μs; Nothing for the world's), checked together so that μs is never below μk.</summary>
    Public Sub SetFriction(body As Shape, kinetic As Double?, [static] As Double?)
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If kinetic.HasValue Then Shape.CheckCoefficient(kinetic.Value, NameOf(kinetic))
        If [static].HasValue Then Shape.CheckCoefficient([static].Value, NameOf([static]))
        Dim k = If(kinetic, _friction)
        If [static].HasValue AndAlso [static].Value < k Then Throw New ArgumentOutOfRangeException(NameOf([static]), "static friction must be at least friction (" & k.ToString(Globalization.CultureInfo.InvariantCulture) & ")")
        body.Friction = kinetic
        body.StaticFriction = [static]
        _solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>Sets a movable body's drag: C_d (quadratic, with the air's density) and b (linear, N·s/m).</summary>
    Public Sub SetDrag(body As Shape, dragCoefficient As Double, linearDrag As Double)
        CheckMovable(body)
        Shape.CheckCoefficient(dragCoefficient, NameOf(dragCoefficient))
        Shape.CheckCoefficient(linearDrag, NameOf(linearDrag))
        body.DragCoefficient = dragCoefficient
        body.LinearDrag = linearDrag
        _solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>μk of a body's surface (its own, else the world's), for the contacts it makes.</summary>
    Public Function KineticFrictionOf(body As Shape) As Double
        If body Is Nothing Then Return _friction
        Return If(body.Friction, _friction)
    End Function

    ''' <summary>μs of a body's surface (its own; else its own μk; else the world's), never below its μk. Nothing: a wall's, the world's.</summary>
    Public Function StaticFrictionOf(body As Shape) As Double
        Dim worldStatic = If(_staticFriction, _friction)
        If body Is Nothing Then Return Math.Max(worldStatic, _friction)
        Dim s = If(body.StaticFriction, If(body.Friction, worldStatic))
        Return Math.Max(s, KineticFrictionOf(body))
    End Function

    ''' <summary>
    ''' Whether some contact can have friction: a movable body that is not a circle has a rough surface (its own
    ''' μk, or the world's) and something rough to touch. The walls and every surface without its own μ take the
    ''' world's, so a world μk above 0 is enough; else another body that is not a circle must have its own μk above
    ''' 0 (a contact's μ is the geometric mean of its two surfaces', so one rough surface alone among icy ones rubs
    ''' nothing). Circles take no friction (they would roll) and two fixed bodies never rub, so a world whose
    ''' movable bodies are all circles has none: the event solver keeps its frictionless path for it.
    ''' </summary>
    Public ReadOnly Property HasFriction As Boolean
        Get
            Dim roughMovable = False
            Dim rough = 0
            For Each b In _bodies
                If b.Kind = ShapeKind.Circle OrElse Not (KineticFrictionOf(b) > 0) Then Continue For
                rough += 1
                If Not b.IsFixed Then roughMovable = True
            Next
            Return roughMovable AndAlso (_friction > 0 OrElse rough >= 2)
        End Get
    End Property

    ''' <summary>
    ''' Whether anything here drags or floats a body: a liquid, a movable body with linear drag, or air with a
    ''' movable body that has a drag coefficient. (Friction alone is not counted: it acts only at contacts.)
    ''' </summary>
    Public ReadOnly Property HasDragOrLiquids As Boolean
        Get
            If _liquids.Count > 0 Then Return True
            For Each b In _movables
                If b.LinearDrag > 0 OrElse (_airDensity > 0 AndAlso b.DragCoefficient > 0) Then Return True
            Next
            Return False
        End Get
    End Property

    ''' <summary>
    ''' Energy taken out of the world since it was made, J: by inelastic collisions, friction, drag and spring
    ''' damping. Never negative, never decreasing; <see cref="KineticEnergy"/> + <see cref="PotentialEnergy"/> +
    ''' this stays what the energy was at the start (to rounding with the event solver, within the stepping
    ''' error with the others), until the world is changed by hand.
    ''' </summary>
    Public ReadOnly Property Dissipated As Double
        Get
            Return _dissipated
        End Get
    End Property

    ''' <summary>Called by solvers where energy leaves the world, J (a negative amount, rounding, is ignored).</summary>
    Friend Sub Dissipate(joules As Double)
        If joules > 0 Then _dissipated += joules
    End Sub

    ''' <summary>
    ''' Σ over movable bodies and liquids of the buoyancy's potential energy (<see cref="Buoyancy.Potential"/>), J;
    ''' 0 without liquids.
    ''' </summary>
    Public Function BuoyancyPotentialEnergy() As Double
        If _liquids.Count = 0 Then Return 0
        Dim sum = 0.0
        For Each b In _movables
            For Each l In _liquids
                Dim part = SubmergedArea.Inside(b.Outline, b.Position, l.Min, l.Max)
                If part.Area > 0 Then sum += Buoyancy.Potential(l.Density, _gravity, l.Surface, part)
            Next
        Next
        Return sum
    End Function

    ''' <summary>Puts <see cref="Dissipated"/> back to a value it had (a solver that refused an advance and restored the world).</summary>
    Friend Sub RestoreDissipated(joules As Double)
        _dissipated = joules
    End Sub
End Class
