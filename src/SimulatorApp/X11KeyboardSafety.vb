Option Strict On
Imports System.Runtime.InteropServices

''' <summary>
''' Keeps Mono's X11 keyboard code away from the path that crashes. Mono's WinForms turns each key
''' press into characters with an X input method (XIM): it calls Xutf8LookupString, also on key
''' events it makes up itself. With a locale whose character set is not UTF-8 (LANG unset, "C",
''' "POSIX", which many servers and CI machines have), a key that types a character outside ASCII
''' (é on a French keyboard, ß, €) makes that call crash the whole process with SIGSEGV now and then
''' (measured under Xvfb with a French layout: with XMODIFIERS=@im=none, 3 runs in 3 died within 100
''' random key presses; with the locale C.UTF-8, or with the input method off, none did).
''' Mono reads its switch, MONO_WINFORMS_XIM_STYLE, when WinForms starts, and Xlib reads the locale
''' then too, so both are set here, before the first WinForms call: the input method is turned off
''' (the crashing call is never made; plain key lookup still types é, ß and € in a UTF-8 locale),
''' and a non-UTF-8 character set is replaced by UTF-8 so that those keys still type their letters.
''' A setting the user made (MONO_WINFORMS_XIM_STYLE already set, for an input method for Chinese
''' or Japanese) is kept. On Windows and on .NET this does nothing.
''' </summary>
Friend Module X11KeyboardSafety
    ''' <summary>Mono's switch for its X input method; "disabled" turns it off.</summary>
    Public Const XimStyleVariable As String = "MONO_WINFORMS_XIM_STYLE"

    ''' <summary>What was done, for --trace ("xim disabled, locale C.UTF-8").</summary>
    Public Property Summary As String = "not needed"

    ''' <summary>Call first in Main, before anything touches WinForms.</summary>
    Public Sub Apply()
        If Type.GetType("Mono.Runtime") Is Nothing OrElse Not RuntimeInformation.IsOSPlatform(OSPlatform.Linux) Then Return
        Dim xim = Environment.GetEnvironmentVariable(XimStyleVariable)
        If String.IsNullOrEmpty(xim) Then
            Environment.SetEnvironmentVariable(XimStyleVariable, "disabled")
            xim = "disabled"
        End If
        Summary = "xim " & xim & ", locale " & EnsureUtf8CharacterSet()
    End Sub

    ''' <summary>The character-type locale after making sure it is UTF-8 (unchanged when it already is, or when no UTF-8 locale exists).</summary>
    Private Function EnsureUtf8CharacterSet() As String
        Try
            Dim current = NativeMethods.CurrentCharacterTypeLocale()
            If IsUtf8(current) Then Return current
            For Each candidate In {"C.UTF-8", "C.utf8", "en_US.UTF-8"}
                If NativeMethods.SetCharacterTypeLocale(candidate) Then
                    ' Child processes (a file dialog's helpers) see the same choice.
                    Environment.SetEnvironmentVariable("LC_CTYPE", candidate)
                    Return candidate
                End If
            Next
            Return current & " (no UTF-8 locale installed)"
        Catch ex As DllNotFoundException
            Return "unknown (no libc)"
        Catch ex As EntryPointNotFoundException
            Return "unknown (no setlocale)"
        End Try
    End Function

    Private Function IsUtf8(locale As String) As Boolean
        Dim l = If(locale, "").ToUpperInvariant()
        Return l.Contains("UTF-8") OrElse l.Contains("UTF8")
    End Function

    ''' <summary>glibc's setlocale for the character-type category (the one Xlib's keyboard lookup reads).</summary>
    Private NotInheritable Class NativeMethods
        Private Sub New()
        End Sub

        ''' <summary>LC_CTYPE in glibc.</summary>
        Private Const LcCtype As Integer = 0

        <DllImport("libc", EntryPoint:="setlocale", CharSet:=CharSet.Ansi, BestFitMapping:=False, ThrowOnUnmappableChar:=True)>
        Private Shared Function SetLocale(category As Integer, locale As String) As IntPtr
        End Function

        Public Shared Function CurrentCharacterTypeLocale() As String
            Dim p = SetLocale(LcCtype, Nothing)
            Return If(p = IntPtr.Zero, "", Marshal.PtrToStringAnsi(p))
        End Function

        Public Shared Function SetCharacterTypeLocale(name As String) As Boolean
            Return SetLocale(LcCtype, name) <> IntPtr.Zero
        End Function
    End Class
End Module
