Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Constraints
    ''' <summary>
    ''' Putting bodies of very different masses back on their constraints (<see cref="ConstraintSet.Project"/>): a 1 µg
    ''' ball wedged between a wall and a 484 t ball that rests on the floor. In the mass-weighted metric the ball's two
    ''' rows are one row to 15 digits (the heavy ball's share of the second is 10⁻¹⁵ of it), so the plain factor refused
    ''' them, every step that drifted was refused with them, and the group ended where it began, for ever.
    ''' </summary>
    Public Class SpreadProjectionTests
        Private Const LightMass As Double = 0.000000001 ' kg
        Private Const HeavyMass As Double = 484000.0 ' kg
        Private Const LightRadius As Double = 0.05 ' m
        Private Const HeavyRadius As Double = 0.5 ' m

        ''' <summary>Slot 0 the light ball against the wall x = 0, slot 1 the heavy ball beside it on the floor y = 0.</summary>
        Private Shared Function Rows() As Constraint()
            Dim none = Vector.Zero
            Return {
                Constraint.Plane(0, -1, none, New Vector(1, 0), LightRadius, none, New Vector(0, 1), Double.PositiveInfinity),
                Constraint.Round(1, 0, none, none, LightRadius + HeavyRadius, none, none),
                Constraint.Plane(1, -1, none, New Vector(0, 1), HeavyRadius, none, New Vector(1, 0), Double.PositiveInfinity)}
        End Function

        ''' <summary>x, y, vx, vy of each ball.</summary>
        Private Shared Function State(lightX As Double, heavyX As Double, lightVx As Double, heavyVx As Double) As Double()
            Return {lightX, HeavyRadius, lightVx, 0.0, heavyX, HeavyRadius, heavyVx, 0.0}
        End Function

        <Fact>
        Public Sub ALightBallWedgedBehindAHeavyOne_IsPutBackOnItsRows()
            ' Both pressed 0.1 nm into what holds them, and both moving on in: the drift an integrator leaves.
            Dim y = State(LightRadius - 0.0000000001, 2 * LightRadius + HeavyRadius - 0.0000000002, -0.000001, -0.000000001)
            Dim constraints As New ConstraintSet(Rows(), {1 / LightMass, 1 / HeavyMass})
            Assert.True(constraints.Spread)
            constraints.Project(y)
            Dim lengthError As Double, rateError As Double
            constraints.Drift(y, lengthError, rateError)
            Assert.True(lengthError <= 0.000000000000001, $"still {lengthError} of its size off its rows")
            Assert.True(rateError <= 0.000000000000001, $"still moving {rateError} m/s along a row")
            ' The wall alone places the light ball; the heavy ball is moved out of it, not the light ball into the wall.
            Assert.Equal(LightRadius, y(0), 15)
            Assert.Equal(2 * LightRadius + HeavyRadius, y(4), 14)
            Assert.Equal(0.0, y(2), 15)
            Assert.Equal(0.0, y(6), 15)
        End Sub
    End Class
End Namespace
