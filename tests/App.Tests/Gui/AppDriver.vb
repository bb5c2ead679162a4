Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading

''' <summary>
''' Drives the real window as a person would, through an <see cref="XSession"/> started with
''' --trace: finds controls from the rectangles the app prints, clicks, drags and types with
''' xdotool, and waits for the trace lines that prove an action had its effect.
''' </summary>
Public NotInheritable Class AppDriver
    Implements IDisposable

    Private Shared ReadOnly NewLine As Char() = {ChrW(10)}
    Private ReadOnly _controls As New Dictionary(Of String, (X As Integer, Y As Integer, W As Integer, H As Integer))(StringComparer.Ordinal)
    Private _pointer As (X As Integer, Y As Integer)?
    Private _scale As Double
    Private _originX As Double
    Private _originY As Double

    ''' <summary>The X session the app runs in.</summary>
    Public ReadOnly Property X As XSession

    Public Sub New()
        Me.New(New XSessionOptions())
    End Sub

    ''' <summary>Starts the app with --trace in a session set up as <paramref name="options"/> say.</summary>
    Public Sub New(options As XSessionOptions)
        Me.New(options, Array.Empty(Of String)())
    End Sub

    ''' <summary>Starts the app with --trace (and <paramref name="extraArgs"/>) in a session set up as <paramref name="options"/> say.</summary>
    Public Sub New(options As XSessionOptions, ParamArray extraArgs As String())
        Dim args As New List(Of String) From {"--trace"}
        args.AddRange(extraArgs)
        X = New XSession(options, args.ToArray())
        Try
            WaitFor("^ready$", TimeSpan.FromSeconds(30))
            ReadLayout()
            ' A known starting point for the pointer (see MoveTo), outside every control.
            X.XDo("mousemove", "1", "1")
            _pointer = (1, 1)
            Thread.Sleep(100)
        Catch
            ' No driver reaches the test's Using block, so nothing else would stop the app and Xvfb.
            X.Dispose()
            Throw
        End Try
    End Sub

    ''' <summary>Reads the last layout the app printed (it prints one after each re-layout).</summary>
    Public Sub ReadLayout()
        For Each line In Lines()
            Dim m = Regex.Match(line, "^control (\S+) (-?\d+) (-?\d+) (\d+) (\d+)( fits| cut)?$")
            If m.Success Then _controls(m.Groups(1).Value) = (Int(m.Groups(2).Value), Int(m.Groups(3).Value), Int(m.Groups(4).Value), Int(m.Groups(5).Value))
            m = Regex.Match(line, "^view scale (\S+) origin (\S+) (\S+)$")
            If m.Success Then
                _scale = Dbl(m.Groups(1).Value)
                _originX = Dbl(m.Groups(2).Value)
                _originY = Dbl(m.Groups(3).Value)
            End If
        Next
        If Not _controls.ContainsKey("canvas") OrElse _scale <= 0 Then Throw New InvalidOperationException("the app printed no layout" & vbLf & X.AppOutput())
    End Sub

    ''' <summary>
    ''' The control lines of the last layout the app printed: those since the "ready" before the last
    ''' one (each layout ends with "ready"). Other trace lines can come between them (a table row the
    ''' running scene changes, traced while the layout asks a list where its cells are), so the block is
    ''' not cut short at the first other line; a control printed twice counts once, as printed last.
    ''' </summary>
    Public Function LastLayout() As List(Of String)
        Dim lines = Me.Lines()
        Dim lastReady = Array.LastIndexOf(lines, "ready")
        Dim previousReady = If(lastReady > 0, Array.LastIndexOf(lines, "ready", lastReady - 1), -1)
        Dim byName As New Dictionary(Of String, String)(StringComparer.Ordinal)
        For Each l In lines.Skip(previousReady + 1).Take(lastReady - previousReady - 1)
            If Not l.StartsWith("control ", StringComparison.Ordinal) Then Continue For
            Dim name = l.Split(" "c)(1)
            byName.Remove(name)
            byName(name) = l
        Next
        Return byName.Values.ToList()
    End Function

    ''' <summary>The screen rectangle of a named control, where the app last laid it out (a longer message moves the panel down).</summary>
    Public Function Control(name As String) As (X As Integer, Y As Integer, W As Integer, H As Integer)
        ReadLayout()
        Dim r As (X As Integer, Y As Integer, W As Integer, H As Integer) = Nothing
        If Not _controls.TryGetValue(name, r) Then Throw New KeyNotFoundException("no control '" & name & "' in the layout" & vbLf & X.AppOutput())
        Return r
    End Function

    ''' <summary>The screen pixel of a model point (m) on the canvas.</summary>
    Public Function Screen(worldX As Double, worldY As Double) As (X As Integer, Y As Integer)
        Dim c = Control("canvas")
        Return (c.X + CInt(Math.Round(_originX + worldX * _scale)), c.Y + CInt(Math.Round(_originY - worldY * _scale)))
    End Function

    ''' <summary>The model point (m) at a screen pixel of the canvas, by the last view the app printed.</summary>
    Public Function ToWorld(screenX As Integer, screenY As Integer) As (X As Double, Y As Double)
        Dim c = Control("canvas")
        Return ((screenX - c.X - _originX) / _scale, (_originY - (screenY - c.Y)) / _scale)
    End Function

    ''' <summary>Pixels per metre on the canvas.</summary>
    Public ReadOnly Property Scale As Double
        Get
            Return _scale
        End Get
    End Property

    ''' <summary>Clicks the middle of a named control with the left button (scrolling the side panel to it first).</summary>
    Public Sub Click(name As String)
        Dim r = ScrollIntoView(name)
        ClickAt(r.X + r.W \ 2, r.Y + r.H \ 2)
    End Sub

    ''' <summary>
    ''' When the side panel is scrolled (large fonts on a small screen) and the control is out of its
    ''' view, turns the mouse wheel over the panel until it is in view; returns where it is then.
    ''' </summary>
    Public Function ScrollIntoView(name As String) As (X As Integer, Y As Integer, W As Integer, H As Integer)
        Dim r = Control(name)
        If name = "side" OrElse Not _controls.ContainsKey("side") Then Return r
        Dim side = Control("side")
        If r.X < side.X Then Return r
        For attempt = 1 To 30
            Dim wheel As String
            If r.Y + r.H > side.Y + side.H Then
                wheel = "5"
            ElseIf r.Y < side.Y Then
                wheel = "4"
            Else
                Exit For
            End If
            Dim from = Mark()
            MoveTo(side.X + side.W \ 2, side.Y + side.H \ 2)
            X.XDo("click", wheel)
            ' The app acknowledges each turn once it has handled it (after the new layout, when the panel
            ' moved): any other layout line (a message, a theme) says nothing about this turn.
            WaitFor("^wheel side ", skip:=from)
            r = Control(name)
        Next
        Return r
    End Function

    ''' <summary>Clicks a screen point.</summary>
    Public Sub ClickAt(sx As Integer, sy As Integer, Optional button As Integer = 1)
        MoveTo(sx, sy)
        Thread.Sleep(20)
        X.XDo("click", S(button))
        Thread.Sleep(150)
    End Sub

    ''' <summary>
    ''' Moves the pointer to a screen point and waits until it is there. A move to where the pointer
    ''' already is is skipped: xdotool's --sync would wait for a motion that never comes (about 15 s).
    ''' </summary>
    Public Sub MoveTo(sx As Integer, sy As Integer)
        If _pointer.HasValue AndAlso _pointer.Value.X = sx AndAlso _pointer.Value.Y = sy Then Return
        X.XDo("mousemove", "--sync", S(sx), S(sy))
        _pointer = (sx, sy)
        Thread.Sleep(60)
    End Sub

    ''' <summary>Presses a button at one screen point, moves in steps to another, releases there.</summary>
    Public Sub Drag(button As Integer, fromX As Integer, fromY As Integer, toX As Integer, toY As Integer, Optional steps As Integer = 8)
        MoveTo(fromX, fromY)
        Thread.Sleep(20)
        X.XDo("mousedown", S(button))
        Thread.Sleep(80)
        For k = 1 To steps
            MoveTo(fromX + (toX - fromX) * k \ steps, fromY + (toY - fromY) * k \ steps)
        Next
        Thread.Sleep(80)
        X.XDo("mouseup", S(button))
        Thread.Sleep(150)
    End Sub

    ''' <summary>Presses a button at a screen point (and holds it).</summary>
    Public Sub Press(button As Integer, sx As Integer, sy As Integer)
        MoveTo(sx, sy)
        Thread.Sleep(20)
        X.XDo("mousedown", S(button))
        Thread.Sleep(80)
    End Sub

    ''' <summary>Lets go of a held button where the pointer is.</summary>
    Public Sub Release(button As Integer)
        Thread.Sleep(80)
        X.XDo("mouseup", S(button))
        Thread.Sleep(150)
    End Sub

    ''' <summary>The key each named text box has on the app's "inputs" trace line.</summary>
    Private Shared ReadOnly InputKeys As New Dictionary(Of String, String)(StringComparer.Ordinal) From {
        {"radius", "Radius"}, {"mass", "Mass"}, {"rect-width", "RectangleWidth"}, {"rect-height", "RectangleHeight"},
        {"sides", "Sides"}, {"angle", "PolygonAngle"}, {"stiffness", "Stiffness"},
        {"box-width", "ContainerWidth"}, {"box-height", "ContainerHeight"},
        {"friction", "FrictionKinetic"}, {"static-friction", "FrictionStatic"}}

    ''' <summary>
    ''' Replaces the text of a named text box, as a person would: click, select all, type. Unless told
    ''' not to check, it then waits until the app's trace shows the box holding the text. A click can be
    ''' lost on a loaded machine under Mono, and the keys then go to the box that had the focus: any box
    ''' changed that way is put back and the whole is tried again (at most three times).
    ''' </summary>
    Public Sub TypeInto(name As String, text As String, Optional check As Boolean = True)
        Dim key As String = Nothing
        If Not check OrElse Not InputKeys.TryGetValue(name, key) Then
            TypeKeys(name, text)
            Return
        End If
        For attempt = 1 To 3
            Dim before = Inputs()
            Dim from = Mark()
            TypeKeys(name, text)
            Try
                WaitFor("^inputs .*\b" & key & "=\[" & Regex.Escape(text) & "\]", TimeSpan.FromSeconds(4), from)
            Catch ex As TimeoutException When attempt < 3
            End Try
            Dim after = Inputs()
            For Each other In InputKeys
                Dim was As String = Nothing, now As String = Nothing
                If other.Value = key OrElse Not before.TryGetValue(other.Value, was) OrElse Not after.TryGetValue(other.Value, now) Then Continue For
                If was <> now Then TypeInto(other.Key, was)
            Next
            Dim got As String = Nothing
            If Inputs().TryGetValue(key, got) AndAlso got = text Then Return
        Next
        Throw New TimeoutException("the " & name & " box does not hold '" & text & "' after three tries" & vbLf & X.AppOutput())
    End Sub

    Private Sub TypeKeys(name As String, text As String)
        Click(name)
        X.XDo("key", "ctrl+a")
        X.XDo("key", "BackSpace")
        If text.Length > 0 Then X.XDo("type", "--delay", "30", "--", text)
        Thread.Sleep(100)
    End Sub

    ''' <summary>What the text boxes held at the last "inputs" trace line, read from the boxes themselves.</summary>
    Public Function Inputs() As Dictionary(Of String, String)
        Dim last = Lines().LastOrDefault(Function(l) l.StartsWith("inputs ", StringComparison.Ordinal))
        Dim result As New Dictionary(Of String, String)(StringComparer.Ordinal)
        If last Is Nothing Then Return result
        For Each m As Match In Regex.Matches(last, "(\w+)=\[([^\]]*)\]")
            result(m.Groups(1).Value) = m.Groups(2).Value
        Next
        Return result
    End Function

    ''' <summary>The last trace line that matches; fails, showing the trace, when none does.</summary>
    Public Function LastMatch(pattern As String) As Match
        Dim re As New Regex(pattern)
        For Each line In Lines().Reverse()
            Dim m = re.Match(line)
            If m.Success Then Return m
        Next
        Throw New Xunit.Sdk.XunitException("no trace line matching /" & pattern & "/" & vbLf & X.AppOutput())
    End Function

    ''' <summary>
    ''' Clicks a button that opens a dialog and waits for the dialog. A click that reaches the window
    ''' while a frame is still being worked out can be lost on a loaded machine under Mono; the button
    ''' is then clicked again (at most three times in all).
    ''' </summary>
    Public Function ClickForDialog(button As String, title As String) As String
        For attempt = 1 To 3
            Click(button)
            Try
                Return WaitForWindow(title, If(attempt < 3, 15, 30))
            Catch ex As TimeoutException When attempt < 3
            End Try
        Next
        Throw New InvalidOperationException("unreachable")
    End Function

    ''' <summary>Waits for a visible window with this title (a dialog) and returns its X id. Mono's file dialogs can take many seconds to appear on a busy machine.</summary>
    Public Function WaitForWindow(title As String, Optional timeoutSeconds As Double = 30) As String
        Dim sw = Diagnostics.Stopwatch.StartNew()
        Do
            Dim r = X.Tool("xdotool", "search", "--onlyvisible", "--name", title)
            Dim id = r.StdOut.Split(NewLine, StringSplitOptions.RemoveEmptyEntries).FirstOrDefault()
            If r.ExitCode = 0 AndAlso Not String.IsNullOrWhiteSpace(id) Then Return id.Trim()
            If sw.Elapsed.TotalSeconds > timeoutSeconds Then Throw New TimeoutException("no window '" & title & "'" & vbLf & X.AppOutput())
            Thread.Sleep(200)
        Loop
    End Function

    ''' <summary>Types text into whatever has the keyboard focus, then presses Return.</summary>
    Public Sub TypeAndEnter(text As String)
        X.XDo("type", "--delay", "30", "--", text)
        Thread.Sleep(200)
        X.XDo("key", "Return")
        Thread.Sleep(200)
    End Sub

    ''' <summary>The app's stdout lines so far.</summary>
    Public Function Lines() As String()
        Dim all = X.AppOutput()
        Dim cut = all.IndexOf("--- app stderr ---", StringComparison.Ordinal)
        Dim outPart = If(cut >= 0, all.Substring(0, cut), all)
        Return outPart.Split(NewLine, StringSplitOptions.RemoveEmptyEntries).Select(Function(l) l.TrimEnd(ChrW(13))).ToArray()
    End Function

    ''' <summary>Waits until a stdout line (after the first <paramref name="skip"/> lines) matches the pattern; returns the match.</summary>
    Public Function WaitFor(pattern As String, Optional timeout As TimeSpan = Nothing, Optional skip As Integer = 0) As Match
        Dim limit = If(timeout = TimeSpan.Zero, TimeSpan.FromSeconds(8), timeout)
        Dim sw = Diagnostics.Stopwatch.StartNew()
        Dim re As New Regex(pattern)
        Do
            Dim ls = Lines()
            For i = skip To ls.Length - 1
                Dim m = re.Match(ls(i))
                If m.Success Then Return m
            Next
            If sw.Elapsed > limit Then Throw New TimeoutException("no trace line matching /" & pattern & "/ within " & limit.TotalSeconds & " s" & vbLf & X.AppOutput())
            Thread.Sleep(100)
        Loop
    End Function

    ''' <summary>Waits until <paramref name="count"/> stdout lines after the first <paramref name="skip"/> match the pattern (the app acknowledged that many actions).</summary>
    Public Sub WaitForCount(pattern As String, count As Integer, skip As Integer)
        Dim sw = Diagnostics.Stopwatch.StartNew()
        Dim re As New Regex(pattern)
        Do
            Dim seen = Lines().Skip(skip).Count(Function(l) re.IsMatch(l))
            If seen >= count Then Return
            If sw.Elapsed.TotalSeconds > 8 Then Throw New TimeoutException($"{seen} of {count} trace lines matching /{pattern}/ within 8 s" & vbLf & X.AppOutput())
            Thread.Sleep(100)
        Loop
    End Sub

    ''' <summary>How many stdout lines there are now (to wait only for what comes next).</summary>
    Public Function Mark() As Integer
        Return Lines().Length
    End Function

    ''' <summary>Clicks a control and waits for the trace line that shows its effect.</summary>
    Public Function ClickAndWait(name As String, pattern As String) As Match
        Dim from = Mark()
        Click(name)
        Return WaitFor(pattern, skip:=from)
    End Function

    ''' <summary>
    ''' As <see cref="ClickAndWait"/>, clicking again (up to <paramref name="attempts"/> clicks in all)
    ''' when the effect does not show within 8 s: for a control whose click can be repeated harmlessly
    ''' (choosing a graph), on a loaded machine where a click made while the app is busy can go unseen.
    ''' </summary>
    Public Function ClickAndWaitRepeatable(name As String, pattern As String, attempts As Integer) As Match
        Dim from = Mark()
        For attempt = 1 To attempts
            Click(name)
            Try
                Return WaitFor(pattern, skip:=from)
            Catch ex As TimeoutException When attempt < attempts
            End Try
        Next
        Throw New InvalidOperationException("unreachable: the last attempt throws")
    End Function

    ''' <summary>Pauses, clears the demo scene, and waits until both took effect.</summary>
    Public Sub PauseAndClear()
        ClickAndWait("pause", "^paused t=")
        ClickAndWait("reset", "^reset: 0 bodies")
    End Sub

    ''' <summary>Asks for a circle and places it at a model point; returns the new circle's id.</summary>
    Public Function PlaceCircle(radius As String, mass As String, worldX As Double, worldY As Double) As String
        TypeInto("radius", radius)
        TypeInto("mass", mass)
        ClickAndWait("add-circle", "^adding circle r ")
        Dim p = Screen(worldX, worldY)
        Dim from = Mark()
        MoveTo(p.X - 30, p.Y - 20)
        MoveTo(p.X, p.Y)
        ClickAt(p.X, p.Y)
        Return WaitFor("^placed circle (\S+) at", skip:=from).Groups(1).Value
    End Function

    Public Shared Function Dbl(text As String) As Double
        Return Double.Parse(text, CultureInfo.InvariantCulture)
    End Function

    Private Shared Function Int(text As String) As Integer
        Return Integer.Parse(text, CultureInfo.InvariantCulture)
    End Function

    Private Shared Function S(value As Integer) As String
        Return value.ToString(CultureInfo.InvariantCulture)
    End Function

    Public Sub Dispose() Implements IDisposable.Dispose
        X.Dispose()
    End Sub
End Class
