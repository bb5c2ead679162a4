Option Strict On
Imports System.Diagnostics
Imports System.IO
Imports System.Text
Imports System.Threading

''' <summary>How an <see cref="XSession"/> sets up its screen and starts the app.</summary>
Public NotInheritable Class XSessionOptions
    ''' <summary>The screen, "WIDTHxHEIGHTxDEPTH".</summary>
    Public Property Screen As String = "1400x900x24"
    ''' <summary>The DPI a desktop announces (the Xft.dpi resource); 0 leaves it unset.</summary>
    Public Property Dpi As Integer
    ''' <summary>A keyboard layout for setxkbmap ("fr"); Nothing leaves the default (us).</summary>
    Public Property KeyboardLayout As String
    ''' <summary>Extra environment for the app; a Nothing value removes the variable.</summary>
    Public ReadOnly Property Environment As New Dictionary(Of String, String)(StringComparer.Ordinal)
    ''' <summary>True: start the app through scripts/run.sh, as a teacher does; False: run the exe on Mono directly.</summary>
    Public Property ThroughLauncher As Boolean = True
End Class

''' <summary>
''' A private X server (Xvfb) with the real app (the net48 exe on Mono) running in it, started the
''' way the launcher starts it, driven with xdotool and photographed with ImageMagick's import, as a
''' person at the screen would use it. Dispose ends both. Failure messages carry the app's stdout and stderr.
''' </summary>
Public NotInheritable Class XSession
    Implements IDisposable

    Public Const WindowTitle As String = "Collision Simulator"
    Private Shared ReadOnly Tools As String() = {"Xvfb", "xdotool", "import", "convert", "mono", "setxkbmap", "xprop"}
    Private Shared ReadOnly ScreenSizeQuery As String() = {"getdisplaygeometry"}

    Private ReadOnly _xvfb As Process
    Private ReadOnly _app As Process
    Private ReadOnly _appOut As New StringBuilder()
    Private ReadOnly _appErr As New StringBuilder()
    Private ReadOnly _env As New Dictionary(Of String, String)

    ''' <summary>The X display, for example ":101".</summary>
    Public ReadOnly Property Display As String
    ''' <summary>The app window's X id.</summary>
    Public ReadOnly Property WindowId As String
    ''' <summary>Where screenshots go.</summary>
    Public ReadOnly Property ShotDirectory As String

    ''' <summary>True when running in CI, where GUI tests must run and never skip.</summary>
    Public Shared ReadOnly Property IsCi As Boolean
        Get
            Dim ci = Environment.GetEnvironmentVariable("CI")
            Return Not String.IsNullOrEmpty(ci) AndAlso Not String.Equals(ci, "false", StringComparison.OrdinalIgnoreCase)
        End Get
    End Property

    ''' <summary>The X tools that are not on PATH.</summary>
    Public Shared Function MissingTools() As List(Of String)
        Dim missing As New List(Of String)
        Dim dirs = If(Environment.GetEnvironmentVariable("PATH"), "").Split(Path.PathSeparator)
        For Each t In Tools
            If Not dirs.Any(Function(d) File.Exists(Path.Combine(d, t))) Then missing.Add(t)
        Next
        Return missing
    End Function

    ''' <summary>The built app.</summary>
    Public Shared ReadOnly Property AppExe As String
        Get
            Return Path.Combine(RepoRoot, "src", "SimulatorApp", "bin", Configuration, "net48", "SimulatorApp.exe")
        End Get
    End Property

    ''' <summary>Starts Xvfb and the app with the given arguments, and waits for the window.</summary>
    Public Sub New(ParamArray appArgs As String())
        Me.New(New XSessionOptions(), appArgs)
    End Sub

    ''' <summary>The session's options.</summary>
    Public ReadOnly Property Options As XSessionOptions

    ''' <summary>Starts Xvfb as the options say and the app in it with the given arguments, and waits for the window.</summary>
    Public Sub New(options As XSessionOptions, ParamArray appArgs As String())
        If options Is Nothing Then Throw New ArgumentNullException(NameOf(options))
        Me.Options = options
        Dim missing = MissingTools()
        If missing.Count > 0 Then Throw New InvalidOperationException("GUI test needs " & String.Join(", ", missing) & " (run: bash scripts/install-deps.sh test)")
        If Not File.Exists(AppExe) Then Throw New FileNotFoundException("the app is not built: " & AppExe)
        ShotDirectory = Path.Combine(RepoRoot, "tests", "App.Tests", "bin", "screenshots")
        Directory.CreateDirectory(ShotDirectory)

        _xvfb = StartXvfb(options.Screen, _Display)
        Try
            _env("DISPLAY") = Display
            SetUpDesktop()
            Dim psi As ProcessStartInfo
            If options.ThroughLauncher Then
                psi = New ProcessStartInfo("bash") With {.UseShellExecute = False, .RedirectStandardOutput = True, .RedirectStandardError = True, .WorkingDirectory = RepoRoot}
                psi.ArgumentList.Add(Path.Combine(RepoRoot, "scripts", "run.sh"))
                psi.ArgumentList.Add("--no-build")
                psi.Environment("CONFIGURATION") = Configuration
            Else
                psi = New ProcessStartInfo("mono") With {.UseShellExecute = False, .RedirectStandardOutput = True, .RedirectStandardError = True, .WorkingDirectory = RepoRoot}
                psi.ArgumentList.Add(AppExe)
            End If
            For Each a In appArgs
                psi.ArgumentList.Add(a)
            Next
            psi.Environment("DISPLAY") = Display
            For Each kv In options.Environment
                If kv.Value Is Nothing Then psi.Environment.Remove(kv.Key) Else psi.Environment(kv.Key) = kv.Value
            Next
            _app = New Process With {.StartInfo = psi}
            AddHandler _app.OutputDataReceived, Sub(s, e) If e.Data IsNot Nothing Then SyncLock _appOut : _appOut.AppendLine(e.Data) : End SyncLock
            AddHandler _app.ErrorDataReceived, Sub(s, e) If e.Data IsNot Nothing Then SyncLock _appErr : _appErr.AppendLine(e.Data) : End SyncLock
            _app.Start()
            _app.BeginOutputReadLine()
            _app.BeginErrorReadLine()
            _WindowId = WaitForWindow(TimeSpan.FromSeconds(60))
            Thread.Sleep(1500) ' let the first frames paint
        Catch
            ' No instance reaches a Using block, so nothing else would stop Xvfb and the app.
            Dispose()
            Throw
        End Try
    End Sub

    ''' <summary>
    ''' The desktop the options ask for: a keyboard layout (as a teacher's would be), and the DPI as
    ''' GNOME, KDE and Xfce announce it to X clients, in the Xft.dpi resource.
    ''' </summary>
    Private Sub SetUpDesktop()
        If Not String.IsNullOrEmpty(Options.KeyboardLayout) Then
            Dim r = Tool("setxkbmap", Options.KeyboardLayout)
            If r.ExitCode <> 0 Then Throw New InvalidOperationException("setxkbmap " & Options.KeyboardLayout & " failed: " & r.ToString())
        End If
        If Options.Dpi > 0 Then
            Dim r = Tool("xprop", "-root", "-f", "RESOURCE_MANAGER", "8s", "-set", "RESOURCE_MANAGER", "Xft.dpi:" & vbTab & Options.Dpi.ToString(Globalization.CultureInfo.InvariantCulture) & vbLf)
            If r.ExitCode <> 0 Then Throw New InvalidOperationException("xprop could not set Xft.dpi: " & r.ToString())
        End If
    End Sub

    ''' <summary>Xvfb on a free display from :101 (ready when it answers xdotool), or an exception saying it could not start.</summary>
    Private Shared Function StartXvfb(screen As String, ByRef display As String) As Process
        Dim n As Integer
        Dim p = XDisplays.StartServer("Xvfb", 101, 160, screen, TimeSpan.FromSeconds(15), AddressOf Answers, n)
        If p Is Nothing Then Throw New InvalidOperationException("could not start Xvfb on any display from :101 to :160")
        display = ":" & n.ToString(Globalization.CultureInfo.InvariantCulture)
        Return p
    End Function

    ''' <summary>Whether the X server on display n answers a client (xdotool asks for the screen size).</summary>
    Private Shared Function Answers(n As Integer) As Boolean
        Try
            Dim r = ProcessRunner.Run("xdotool", ScreenSizeQuery, New Dictionary(Of String, String) From {{"DISPLAY", ":" & n.ToString(Globalization.CultureInfo.InvariantCulture)}}, TimeSpan.FromSeconds(10))
            Return r.ExitCode = 0
        Catch ex As TimeoutException
            Return False ' not answering yet; the caller's own time limit decides
        End Try
    End Function

    Private Function WaitForWindow(timeout As TimeSpan) As String
        Dim sw = Stopwatch.StartNew()
        Do While sw.Elapsed < timeout
            If _app.HasExited Then Throw New InvalidOperationException("the app exited (code " & _app.ExitCode & ") before showing its window" & vbLf & AppOutput())
            ' Mono's forms carry no _NET_WM_PID, so search by title (see shared/notes/linux-gui.md).
            Dim r = Tool("xdotool", "search", "--onlyvisible", "--name", WindowTitle)
            Dim id = r.StdOut.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries).FirstOrDefault()
            If r.ExitCode = 0 AndAlso Not String.IsNullOrWhiteSpace(id) Then Return id.Trim()
            Thread.Sleep(250)
        Loop
        Throw New TimeoutException("no window titled '" & WindowTitle & "' within " & timeout.TotalSeconds & " s" & vbLf & AppOutput())
    End Function

    ''' <summary>Runs an X tool against this display.</summary>
    Public Function Tool(name As String, ParamArray args As String()) As ProcessResult
        Return ProcessRunner.Run(name, args, _env, TimeSpan.FromSeconds(30))
    End Function

    ''' <summary>Runs xdotool and fails, with the app's output, when it fails.</summary>
    Public Sub XDo(ParamArray args As String())
        Dim r = Tool("xdotool", args)
        If r.ExitCode <> 0 Then Throw New InvalidOperationException("xdotool " & String.Join(" ", args) & " failed: " & r.ToString() & vbLf & AppOutput())
    End Sub

    ''' <summary>
    ''' Photographs the window: keeps a PNG (for people) named after the test and returns the pixels.
    ''' </summary>
    Public Function Shoot(name As String) As Screenshot
        If String.IsNullOrEmpty(WindowId) Then Throw New InvalidOperationException("no window id: import without one would wait for a click forever")
        Dim png = Path.Combine(ShotDirectory, name & ".png")
        Dim ppm = Path.Combine(ShotDirectory, name & ".ppm")
        Dim r = Tool("import", "-window", WindowId, png)
        If r.ExitCode <> 0 Then Throw New InvalidOperationException("import failed: " & r.ToString() & vbLf & AppOutput())
        r = Tool("convert", png, "-depth", "8", "ppm:" & ppm)
        If r.ExitCode <> 0 Then Throw New InvalidOperationException("convert failed: " & r.ToString())
        Return Screenshot.ReadPpm(ppm)
    End Function

    ''' <summary>The app's stdout and stderr so far, for failure messages.</summary>
    Public Function AppOutput() As String
        SyncLock _appOut
            SyncLock _appErr
                Return "--- app stdout ---" & vbLf & _appOut.ToString() & "--- app stderr ---" & vbLf & _appErr.ToString()
            End SyncLock
        End SyncLock
    End Function

    ''' <summary>True while the app is still running.</summary>
    Public ReadOnly Property AppIsRunning As Boolean
        Get
            Return Not _app.HasExited
        End Get
    End Property

    Public Sub Dispose() Implements IDisposable.Dispose
        For Each p In {_app, _xvfb}
            Try
                ' Xvfb is asked to stop (SIGTERM) so that it removes its lock file and socket.
                If p Is _xvfb Then XDisplays.StopServer(p)
                If p IsNot Nothing AndAlso Not p.HasExited Then p.Kill(True)
                p?.WaitForExit(5000)
            Catch ex As InvalidOperationException
                ' already gone
            End Try
            p?.Dispose()
        Next
    End Sub
End Class
