Option Strict On
Imports System.Globalization

Namespace Generation
    ''' <summary>
    ''' A scene while ingredients add to it: the random source, the world, the bodies placed so far, how
    ''' many more may come, and the scene's own ranges of size, mass and speed that ingredients draw from.
    ''' </summary>
    Friend NotInheritable Class SceneBuilder
        Private ReadOnly _counters As New Dictionary(Of String, Integer)(StringComparer.Ordinal)

        Friend Sub New(rng As SplitMix, world As WorldDraft, kinds As BodyKinds, budget As Integer)
            Me.Rng = rng
            Me.World = world
            Me.Kinds = kinds
            Me.Budget = budget
            DrawRanges()
        End Sub

        Friend ReadOnly Property Rng As SplitMix
        Friend ReadOnly Property World As WorldDraft
        Friend ReadOnly Property Kinds As BodyKinds
        Friend ReadOnly Property Bodies As New List(Of BodyDraft)
        Friend ReadOnly Property Links As New List(Of LinkDraft)
        ''' <summary>Ingredients applied, in order (with repeats).</summary>
        Friend ReadOnly Property Used As New List(Of String)
        ''' <summary>How many more bodies may be added.</summary>
        Friend Property Budget As Integer
        ''' <summary>This scene's radii, m.</summary>
        Friend Property RadiusMin As Double
        Friend Property RadiusMax As Double
        ''' <summary>This scene's masses, kg.</summary>
        Friend Property MassMin As Double
        Friend Property MassMax As Double
        ''' <summary>The fastest a body starts in this scene, m/s (0: everything starts at rest).</summary>
        Friend Property SpeedTop As Double

        ''' <summary>The widest range of radii, m: 1 mm to 2 m, narrowed so that a ball fits many times in a small container.</summary>
        Friend ReadOnly Property RadiusCeiling As Double
            Get
                Return Math.Min(2.0, Math.Min(World.Width, World.Height) / 8)
            End Get
        End Property

        Friend ReadOnly Property RadiusFloor As Double
            Get
                Return Math.Min(0.001, RadiusCeiling / 4)
            End Get
        End Property

        Friend Function Has(kind As BodyKinds) As Boolean
            Return (Kinds And kind) = kind
        End Function

        ' Half the scenes mix every size, mass and speed (the hard cases: mm balls among metre balls, grams
        ' against tonnes); the others keep them close, as a classroom scene would.
        Private Sub DrawRanges()
            Dim lo = RadiusFloor, hi = RadiusCeiling
            If Rng.Chance(0.5) Then
                RadiusMin = lo
                RadiusMax = hi
            Else
                Dim centre = Rng.LogUniform(lo, hi)
                RadiusMin = Math.Max(lo, centre / 1.5)
                RadiusMax = Math.Min(hi, centre * 1.5)
            End If
            Dim m = Rng.NextDouble()
            If m < 0.45 Then
                MassMin = 0.000001
                MassMax = 1000000.0
            ElseIf m < 0.8 Then
                Dim centre = Rng.LogUniform(0.000001, 1000000.0)
                MassMin = centre / 3
                MassMax = centre * 3
            Else
                MassMin = Rng.LogUniform(0.000001, 1000000.0)
                MassMax = MassMin
            End If
            ' Everything at rest is a test only when gravity moves it.
            SpeedTop = If(World.Gravity > 0 AndAlso Rng.Chance(0.15), 0.0, Rng.LogUniform(0.01, 10000.0))
        End Sub

        ''' <summary>A fresh id: the prefix and the next number for it ("c0", "c1", …).</summary>
        Friend Function NewId(prefix As String) As String
            Dim n = 0
            _counters.TryGetValue(prefix, n)
            _counters(prefix) = n + 1
            Return prefix & n.ToString(CultureInfo.InvariantCulture)
        End Function

        Friend Function Radius() As Double
            Return Rng.LogUniform(RadiusMin, RadiusMax)
        End Function

        Friend Function Mass() As Double
            Return Rng.LogUniform(MassMin, MassMax)
        End Function

        ''' <summary>At rest a quarter of the time; otherwise a random direction at a speed log-uniform up to <see cref="SpeedTop"/>.</summary>
        Friend Function Velocity() As Vector
            If SpeedTop = 0 OrElse Rng.Chance(0.25) Then Return Vector.Zero
            Return Rng.Direction() * Rng.LogUniform(SpeedTop * 0.001, SpeedTop)
        End Function

        ''' <summary>Along x only (a ball rolling along a surface), at rest half the time.</summary>
        Friend Function Sliding() As Vector
            If SpeedTop = 0 OrElse Rng.Chance(0.5) Then Return Vector.Zero
            Return New Vector(If(Rng.Chance(0.5), -1, 1) * Rng.LogUniform(SpeedTop * 0.001, SpeedTop), 0)
        End Function

        ''' <summary>A point where a circle of radius r lies inside the container.</summary>
        Friend Function PointInside(r As Double) As Vector
            Return New Vector(Rng.Uniform(r, World.Width - r), Rng.Uniform(r, World.Height - r))
        End Function

        ''' <summary>A movable circle of this scene's sizes at <paramref name="centre"/>.</summary>
        Friend Function Ball(centre As Vector, r As Double, Optional velocity As Vector? = Nothing) As BodyDraft
            Return BodyDraft.MovableCircle(NewId("c"), centre, r, Mass(), If(velocity, Me.Velocity()))
        End Function

        ''' <summary>Whether <paramref name="b"/> may join the scene now (budget and the reader's rules).</summary>
        Friend Function Fits(b As BodyDraft) As Boolean
            Return Budget > 0 AndAlso Placement.Fits(World, Bodies, b)
        End Function

        ''' <summary>Adds <paramref name="b"/> when it fits; False (and nothing added) otherwise.</summary>
        Friend Function TryAdd(b As BodyDraft) As Boolean
            If Not Fits(b) Then Return False
            Bodies.Add(b)
            Budget -= 1
            Return True
        End Function

        ''' <summary>Adds every body or none: each must fit with the scene and with the ones before it.</summary>
        Friend Function TryAddAll(group As IReadOnlyList(Of BodyDraft)) As Boolean
            If group.Count > Budget Then Return False
            For i = 0 To group.Count - 1
                If Not Placement.Fits(World, Bodies.Concat(group.Take(i)), group(i)) Then Return False
            Next
            Bodies.AddRange(group)
            Budget -= group.Count
            Return True
        End Function

        ''' <summary>Level surfaces at least <paramref name="width"/> m wide inside the container: the floor (walls on) and rectangle tops.</summary>
        Friend Function Supports(width As Double) As List(Of Support)
            Dim list As New List(Of Support)
            If World.Walls Then list.Add(New Support(0, 0, World.Width))
            For Each b In Bodies
                If b.Shape <> DraftShape.Rectangle OrElse Not b.IsFixed Then Continue For
                Dim left = Math.Max(b.Position.X, 0)
                Dim right = Math.Min(b.Corner.X, World.Width)
                If right - left >= width AndAlso b.Corner.Y >= 0 AndAlso b.Corner.Y < World.Height Then list.Add(New Support(b.Corner.Y, left, right))
            Next
            Return list.Where(Function(s) s.Right - s.Left >= width).ToList()
        End Function

        ''' <summary>Fixed rectangles placed so far.</summary>
        Friend Function FixedRectangles() As List(Of BodyDraft)
            Return Bodies.Where(Function(b) b.Shape = DraftShape.Rectangle AndAlso b.IsFixed).ToList()
        End Function
    End Class
End Namespace
