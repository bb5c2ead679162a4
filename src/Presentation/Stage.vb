Option Strict On

''' <summary>
''' What the presenter's parts share, and all they see of one another: the world on show, the
''' window, the trace, the message, the collision log, the typed boxes, whether time is stopped,
''' and the few things any part may ask for (a snapshot for the tables, the end of the mouse's
''' gestures, a new run for a new world). Each part (time travel, graphs, export, lessons, table
''' editing, momentum views, the pointer tools, the undo history) keeps its own state and is handed
''' this; <see cref="SimulationPresenter"/> builds them and routes the window's calls to them.
''' </summary>
Friend NotInheritable Class Stage
    Private _messageHolds As Func(Of Boolean)

    Public Sub New(window As ISimulationView)
        Me.Window = window
    End Sub

    ''' <summary>The window (or a test's recorder).</summary>
    Public ReadOnly Property Window As ISimulationView

    ''' <summary>The world on show. Replaced when a scene is opened, restarted, or a moment of the run is taken back.</summary>
    Public Property World As World

    ''' <summary>Receives one line per action and state change (the app's --trace switch); Nothing without one.</summary>
    Public Property Trace As Action(Of String)

    ''' <summary>The last collisions, newest first.</summary>
    Public ReadOnly Property Log As New CollisionLog()

    ''' <summary>The text of the input boxes, as typed.</summary>
    Public ReadOnly Property Inputs As New BodyInputs()

    ''' <summary>True while time is stopped.</summary>
    Public Property IsPaused As Boolean

    ''' <summary>The message on show ("" for none).</summary>
    Public ReadOnly Property Message As String = ""

    ''' <summary>Whether a trace is listening (lines that cost something to build are built only then).</summary>
    Public ReadOnly Property Tracing As Boolean
        Get
            Return Trace IsNot Nothing
        End Get
    End Property

    ''' <summary>Writes one line to the trace.</summary>
    Public Sub Emit(line As String)
        Trace?.Invoke(line)
    End Sub

    ''' <summary>
    ''' Shows a message and writes it to the trace. A message that is true only for a while (Delete
    ''' mode is on, the run ahead can be replayed, the scene cannot keep up) comes with
    ''' <paramref name="holds"/>, and goes as soon as that is no longer so (see <see cref="CheckMessage"/>).
    ''' </summary>
    Public Sub ShowMessage(text As String, Optional holds As Func(Of Boolean) = Nothing)
        _Message = If(text, "")
        _messageHolds = If(_Message.Length > 0, holds, Nothing)
        If _Message.Length > 0 Then Emit("message: " & _Message)
        Window.ShowMessage(_Message)
    End Sub

    ''' <summary>After every change and every frame: a message that is no longer true goes.</summary>
    Public Sub CheckMessage()
        Dim holds = _messageHolds
        If holds Is Nothing OrElse holds() Then Return
        _messageHolds = Nothing
        Emit("message gone: " & _Message)
        ShowMessage("")
    End Sub

    Private _takeSnapshot As Action
    Private _endGestures As Action
    Private _present As Action(Of World)
    Private _carrying As Func(Of Boolean)

    ''' <summary>What the presenter does for every part: take a snapshot, end the gestures, put a new world on show, say whether a hand carries a body.</summary>
    Public Sub Connect(takeSnapshot As Action, endGestures As Action, present As Action(Of World), carrying As Func(Of Boolean))
        _takeSnapshot = takeSnapshot
        _endGestures = endGestures
        _present = present
        _carrying = carrying
    End Sub

    ''' <summary>Whether the teacher is carrying a body with the mouse now.</summary>
    Public ReadOnly Property IsCarrying As Boolean
        Get
            Return _carrying.Invoke()
        End Get
    End Property

    ''' <summary>Copies the world's state for the tables and totals and tells the window.</summary>
    Public Sub TakeSnapshot()
        _takeSnapshot.Invoke()
    End Sub

    ''' <summary>Ends any carry, aim or tool in progress.</summary>
    Public Sub EndGestures()
        _endGestures.Invoke()
    End Sub

    ''' <summary>
    ''' Puts a new world on show (a scene opened, a restart, an empty box): ends the gestures, drops
    ''' the body being placed, and starts a new run with it.
    ''' </summary>
    Public Sub Present(w As World)
        _present.Invoke(w)
    End Sub

    ''' <summary>
    ''' Runs one of the teacher's actions. Anything the engine refuses becomes a message, never a
    ''' crash; the tables are brought up to date either way.
    ''' </summary>
    Public Sub Guarded(action As Action)
        Try
            action()
        Catch ex As ArgumentException
            ShowMessage("That did not work: " & OneLine(ex.Message))
        Catch ex As InvalidOperationException
            ShowMessage("That did not work: " & OneLine(ex.Message))
        Catch ex As ArithmeticException
            ShowMessage("That did not work: " & OneLine(ex.Message))
        Catch ex As NotSupportedException
            ShowMessage("That did not work: " & OneLine(ex.Message))
        Catch ex As Scenes.SceneFormatException
            ShowMessage("That did not work: " & OneLine(ex.Message))
        End Try
    End Sub

    ''' <summary>The text on one line (a message from the engine may hold line breaks).</summary>
    Public Shared Function OneLine(text As String) As String
        Return If(text, "").Replace(vbCr, " ").Replace(vbLf, " ").Trim()
    End Function

    ''' <summary>
    ''' "radius set to the maximum, 2.00 m. " for each value brought to a limit; "" when none was. A
    ''' count (no unit: the sides of a polygon) is written as the whole number it is, "3", not "3.00".
    ''' </summary>
    Public Shared Function ClampNote(ParamArray fields As (Name As String, Input As NumberInput?, Unit As String)()) As String
        Dim notes = fields.Where(Function(f) f.Input.HasValue AndAlso f.Input.Value.WasClamped).
            Select(Function(f) f.Name & " set to the " & If(f.Input.Value.WasRaised, "minimum", "maximum") & ", " &
                               If(f.Unit.Length = 0, f.Input.Value.Value.ToString("0", Globalization.CultureInfo.InvariantCulture), Units.Sig(f.Input.Value.Value) & " " & f.Unit)).ToList()
        If notes.Count = 0 Then Return ""
        Return String.Join(", ", notes) & ". "
    End Function

    ''' <summary>"radius (m) is empty; mass (kg) 'x' is not a number.": what is wrong with each input that was refused.</summary>
    Public Shared Function Problems(ParamArray inputs As NumberInput()) As String
        Return String.Join("; ", inputs.Where(Function(i) Not i.IsValid).Select(Function(i) i.Problem)) & "."
    End Function
End Class
