Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO

''' <summary>
''' X display numbers and the X servers (Xvfb) started on them, for the programs that start their own:
''' the frame benchmark here, and the real-window tests, which compile this same file in
''' (tests/App.Tests).
''' </summary>
Friend Module XDisplays
    ''' <summary>
    ''' The first display number from <paramref name="first"/> to <paramref name="last"/> with neither a
    ''' lock file nor a socket, after clearing the locks of servers that no longer run; −1 if none.
    ''' </summary>
    Friend Function FreeDisplay(first As Integer, last As Integer) As Integer
        For d = first To last
            If IsFree(d) Then Return d
        Next
        Return -1
    End Function

    ''' <summary>Whether display n has neither a lock file nor a socket (a stale lock is cleared first).</summary>
    Friend Function IsFree(display As Integer) As Boolean
        ClearIfStale(display)
        Dim s = display.ToString(CultureInfo.InvariantCulture)
        Return Not File.Exists("/tmp/.X11-unix/X" & s) AndAlso Not File.Exists("/tmp/.X" & s & "-lock")
    End Function

    ''' <summary>
    ''' Frees display n when its lock names a process that no longer runs (an X server that was killed
    ''' without cleaning up); a display whose server is alive is left alone.
    ''' </summary>
    Friend Sub ClearIfStale(display As Integer)
        Dim s = display.ToString(CultureInfo.InvariantCulture)
        Dim lockFile = "/tmp/.X" & s & "-lock"
        If Not File.Exists(lockFile) OrElse Not Directory.Exists("/proc/self") Then Return ' no /proc: cannot tell, leave it
        Try
            Dim pid As Integer
            If Not Integer.TryParse(File.ReadAllText(lockFile).Trim(), NumberStyles.Integer, CultureInfo.InvariantCulture, pid) Then Return
            If pid <= 0 OrElse Directory.Exists("/proc/" & pid.ToString(CultureInfo.InvariantCulture)) Then Return
            File.Delete(lockFile)
            If File.Exists("/tmp/.X11-unix/X" & s) Then File.Delete("/tmp/.X11-unix/X" & s)
        Catch ex As IOException
            ' in use or being freed by someone else: try the next number
        Catch ex As UnauthorizedAccessException
            ' not ours to free
        End Try
    End Sub

    ''' <summary>
    ''' Starts an X server (<paramref name="xvfb"/>, the Xvfb program) with one screen of
    ''' <paramref name="screen"/> (e.g. "1280x1024x24") on the first free display from
    ''' <paramref name="first"/> to <paramref name="last"/>, and waits until it is ready: its socket
    ''' exists, <paramref name="answers"/> says a client got an answer, and the process still runs
    ''' (another server started at the same moment on the same number may own the socket). A display
    ''' where it is not ready within <paramref name="wait"/> is given up and the next one tried.
    ''' Returns the server and sets <paramref name="display"/>; Nothing when no display worked.
    ''' </summary>
    Friend Function StartServer(xvfb As String, first As Integer, last As Integer, screen As String, wait As TimeSpan,
                                answers As Func(Of Integer, Boolean), ByRef display As Integer) As Process
        For n = first To last
            If Not IsFree(n) Then Continue For
            Dim s = n.ToString(CultureInfo.InvariantCulture)
            Dim psi As New ProcessStartInfo(xvfb) With {.UseShellExecute = False, .RedirectStandardError = True, .RedirectStandardOutput = True}
            ' -noreset: without it, Xvfb resets itself whenever its last client leaves, so a readiness
            ' probe (a client that connects and leaves) could reset it just as the real client connects.
            ' -r: no auto-repeat, so a key held down by a slow, loaded machine (the release arriving late)
            ' types once, as it was pressed, not twice.
            For Each a In {":" & s, "-screen", "0", screen, "-nolisten", "tcp", "-noreset", "-r"}
                psi.ArgumentList.Add(a)
            Next
            Dim p = Process.Start(psi)
            p.BeginErrorReadLine()
            p.BeginOutputReadLine()
            Dim clock = Stopwatch.StartNew()
            Do While clock.Elapsed < wait AndAlso Not p.HasExited
                ' The socket appears before the server takes connections.
                If File.Exists("/tmp/.X11-unix/X" & s) AndAlso answers(n) AndAlso Not p.HasExited Then
                    display = n
                    Return p
                End If
                Threading.Thread.Sleep(100)
            Loop
            StopServer(p)
            p.Dispose()
        Next
        Return Nothing
    End Function

    ''' <summary>
    ''' Stops an X server politely (SIGTERM, so it removes its lock file and socket; a killed one leaves
    ''' them behind and the display stays taken), then for good if it has not gone within 5 s.
    ''' </summary>
    Friend Sub StopServer(server As Process)
        If server Is Nothing OrElse server.HasExited Then Return
        Try
            Using term = Process.Start(New ProcessStartInfo("kill", "-TERM " & server.Id.ToString(CultureInfo.InvariantCulture)) With {.UseShellExecute = False})
                term.WaitForExit(5000)
            End Using
            server.WaitForExit(5000)
        Catch ex As ComponentModel.Win32Exception
            ' no kill command: fall through to Kill
        End Try
        If Not server.HasExited Then server.Kill()
    End Sub
End Module
