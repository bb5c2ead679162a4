Option Strict On
Imports System.Collections.Concurrent
Imports System.IO

Namespace Workers
    ''' <summary>
    ''' A fixed number of checkers lent out one at a time: worker processes (each with its own scratch
    ''' file in a scratch folder that is removed at the end), or in-process checkers.
    ''' </summary>
    Friend NotInheritable Class WorkerPool
        Implements IDisposable

        Private ReadOnly _all As New List(Of ISceneChecker)
        Private ReadOnly _free As New BlockingCollection(Of ISceneChecker)()
        Private ReadOnly _scratch As String

        ''' <param name="size">how many checks may run at once</param>
        ''' <param name="inProcess">check in this process instead of in workers</param>
        Friend Sub New(size As Integer, inProcess As Boolean)
            If size < 1 Then Throw New ArgumentOutOfRangeException(NameOf(size), "at least one worker")
            If Not inProcess Then
                _scratch = Path.Combine(Path.GetTempPath(), "fuzz-" & Environment.ProcessId.ToString(Globalization.CultureInfo.InvariantCulture) & "-" & Guid.NewGuid().ToString("N"))
                Directory.CreateDirectory(_scratch)
            End If
            For i = 1 To size
                Dim checker As ISceneChecker
                If inProcess Then
                    checker = New InProcessChecker()
                Else
                    checker = New WorkerProcess(Path.Combine(_scratch, "scene-" & i.ToString(Globalization.CultureInfo.InvariantCulture) & ".json"))
                End If
                _all.Add(checker)
                _free.Add(checker)
            Next
        End Sub

        ''' <summary>How many checks may run at once.</summary>
        Friend ReadOnly Property Size As Integer
            Get
                Return _all.Count
            End Get
        End Property

        ''' <summary>Runs <paramref name="work"/> with a checker no one else is using.</summary>
        Friend Function [With](Of T)(work As Func(Of ISceneChecker, T)) As T
            Dim checker = _free.Take()
            Try
                Return work(checker)
            Finally
                _free.Add(checker)
            End Try
        End Function

        Public Sub Dispose() Implements IDisposable.Dispose
            For Each c In _all
                TryCast(c, IDisposable)?.Dispose()
            Next
            _free.Dispose()
            If _scratch IsNot Nothing AndAlso Directory.Exists(_scratch) Then Directory.Delete(_scratch, recursive:=True)
        End Sub
    End Class
End Namespace
