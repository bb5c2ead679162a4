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
