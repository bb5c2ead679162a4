Option Strict On
Imports System.Runtime.InteropServices
Imports System.Threading

''' <summary>
''' Ctrl+C or SIGTERM during a run: the temporary output files are thrown away, one line on standard
''' error says so, and the process exits with status 1 (cli.md: any other failure). The main thread
''' may be writing to those files at that moment; it must not report the closed file on top, so it
''' asks <see cref="Interrupted"/> before it reports anything. Once the outputs are being committed
''' the run is let finish (that takes milliseconds), so a file is never half moved into place.
''' </summary>
Friend NotInheritable Class RunInterruption
    Implements IDisposable

    Private ReadOnly _discard As Func(Of IReadOnlyList(Of String))
    Private ReadOnly _cancel As ConsoleCancelEventHandler
    Private ReadOnly _terminate As PosixSignalRegistration
    Private _state As Integer ' Running, Finishing or Stopped (Interlocked)
    Private Const StateRunning As Integer = 0
    Private Const StateFinishing As Integer = 1
    Private Const StateStopped As Integer = 2

    ''' <summary>
    ''' Starts listening; <paramref name="discard"/> throws the temporary outputs away and returns the
    ''' outputs that are streams (a FIFO, /dev/stdout), which were written straight through and so
    ''' already hold the start of their table.
    ''' </summary>
    Friend Sub New(discard As Func(Of IReadOnlyList(Of String)))
        _discard = discard
        _cancel = Sub(sender, e)
                      e.Cancel = True
                      [Stop]("Ctrl+C (SIGINT)")
                  End Sub
        AddHandler Console.CancelKeyPress, _cancel
        _terminate = PosixSignalRegistration.Create(PosixSignal.SIGTERM,
            Sub(context)
                context.Cancel = True
                [Stop]("SIGTERM")
            End Sub)
    End Sub

    ''' <summary>True once a signal has stopped the run (the process is exiting).</summary>
    Friend ReadOnly Property Interrupted As Boolean
        Get
            Return Volatile.Read(_state) = StateStopped
        End Get
    End Property

    ''' <summary>The outputs are complete and being committed: a signal from now on is ignored.</summary>
    Friend Sub Finishing()
        Interlocked.CompareExchange(_state, StateFinishing, StateRunning)
    End Sub

    Private Sub [Stop](signal As String)
        If Interlocked.CompareExchange(_state, StateStopped, StateRunning) <> StateRunning Then Return
        Dim streamed = _discard()
        Dim line = "run: interrupted by " & signal & "; no output file was written"
        If streamed.Count > 0 Then line &= " (the table streamed into " & String.Join(" and ", streamed.Select(Function(p) "'" & p & "'")) & " stopped part-way)"
        Console.Error.WriteLine(line)
        Environment.Exit(ExitCodes.Failure)
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        RemoveHandler Console.CancelKeyPress, _cancel
        _terminate.Dispose()
    End Sub
End Class
