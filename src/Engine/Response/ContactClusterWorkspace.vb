Option Strict On

''' <summary>
''' Scratch memory for <see cref="ContactCluster.Resolve"/>, kept between calls so that a solver that
''' resolves clusters during a run does not allocate the matrices each time. Holds no results: the
''' same input gives the same output with a fresh or a used workspace. Not for two threads at once.
''' </summary>
Public NotInheritable Class ContactClusterWorkspace
    Friend ReadOnly Projection As New ContactProjection()
    ' Per slot (x, y), m/s: before, after compression, after restitution, after a second projection.
    Friend Before As Double() = Array.Empty(Of Double)()
    Friend Compressed As Double() = Array.Empty(Of Double)()
    Friend Restituted As Double() = Array.Empty(Of Double)()
    Friend SecondProjection As Double() = Array.Empty(Of Double)()
    ' Per contact, N·s.
    Friend CompressionImpulses As Double() = Array.Empty(Of Double)()
    Friend SecondImpulses As Double() = Array.Empty(Of Double)()

    Friend Sub Grow(slots As Integer, contacts As Integer)
        HouseholderQr.Grow(Before, 2 * slots)
        HouseholderQr.Grow(Compressed, 2 * slots)
        HouseholderQr.Grow(Restituted, 2 * slots)
        HouseholderQr.Grow(SecondProjection, 2 * slots)
        HouseholderQr.Grow(CompressionImpulses, contacts)
        HouseholderQr.Grow(SecondImpulses, contacts)
    End Sub
End Class
