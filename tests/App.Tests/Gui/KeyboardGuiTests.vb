Option Strict On
Imports System.Threading
Imports Xunit

''' <summary>
''' Letters beyond ASCII, typed as a French or German teacher would, in every text box and in the
''' file dialogs, many times over. Under Mono's X input method, in a locale that is not UTF-8, such a
''' key could kill the app (SIGSEGV in Xutf8LookupString); XMODIFIERS=@im=none made it happen within
''' about a hundred key presses. The app must survive, and the letters must arrive.
''' </summary>
<Collection(RealWindow.Name)>
Public Class KeyboardGuiTests
    Private Shared ReadOnly Boxes As String() = {"radius", "mass", "rect-width", "rect-height", "box-width", "box-height"}
    Private Shared ReadOnly Fields As String() = {"Radius", "Mass", "RectangleWidth", "RectangleHeight", "ContainerWidth", "ContainerHeight"}
    ''' <summary>Keys of the French layout that type accented letters and symbols.</summary>
    Private Shared ReadOnly FrenchKeys As String() = {"eacute", "egrave", "agrave", "ccedilla", "ugrave", "twosuperior", "section", "mu", "sterling", "degree"}

    ''' <summary>The setting that crashed most often: a French keyboard, no locale, and Xlib's own input method.</summary>
    Private Shared Function CrashProne(throughLauncher As Boolean) As XSessionOptions
        Dim o As New XSessionOptions With {.KeyboardLayout = "fr", .ThroughLauncher = throughLauncher}
        For Each name In {"LANG", "LC_ALL", "LC_CTYPE", "LANGUAGE", "MONO_WINFORMS_XIM_STYLE"}
            o.Environment(name) = Nothing
        Next
        o.Environment("XMODIFIERS") = "@im=none"
        Return o
    End Function

    <GuiFact>
    Public Sub AccentedKeys_InEveryBoxAndDialog_StartedByTheLauncher()
        TypeEverywhere(CrashProne(throughLauncher:=True), rounds:=2)
    End Sub

    <GuiFact>
    Public Sub AccentedKeys_InEveryBoxAndDialog_StartedWithoutTheLauncher()
        ' The app makes itself safe too, for anyone who starts the exe with mono directly.
        TypeEverywhere(CrashProne(throughLauncher:=False), rounds:=3)
    End Sub

    ''' <summary>
    ''' Types the accented text and keys into box i, and returns what the box then shows. The app must
    ''' survive every key. xdotool types a character the keyboard map lacks by remapping a spare key
    ''' for a moment, which a heavily loaded machine can race (a character lost or doubled), so the
    ''' box is given up to 5 s to show the text, and is typed into again (up to three times in all)
    ''' when it does not.
    ''' </summary>
    Private Shared Function TypeAccents(app As AppDriver, i As Integer) As String
        Dim shown = ""
        For attempt = 1 To 3
            app.Click(Boxes(i))
            app.X.XDo("key", "ctrl+a")
            app.X.XDo("key", "BackSpace")
            app.X.XDo("type", "--delay", "20", "--", "é€ß²µ§àçù")
            For Each k In FrenchKeys
                app.X.XDo("key", k)
            Next
            Dim clock = Diagnostics.Stopwatch.StartNew()
            Do
                Thread.Sleep(150)
                Assert.True(app.X.AppIsRunning, "the app died typing in " & Boxes(i) & vbLf & app.X.AppOutput())
                shown = app.Inputs()(Fields(i))
                If shown.StartsWith("é€ß²µ§àçù", StringComparison.Ordinal) AndAlso shown.Contains("éèàçù", StringComparison.Ordinal) Then Return shown
            Loop While clock.Elapsed < TimeSpan.FromSeconds(5)
        Next
        Return shown
    End Function

    Private Shared Sub TypeEverywhere(options As XSessionOptions, rounds As Integer)
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-kbd-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Try
            Using app As New AppDriver(options)
                app.WaitFor("^keyboard xim disabled, locale C.UTF-8$")
                For round = 1 To rounds
                    For i = 0 To Boxes.Length - 1
                        Dim shown = TypeAccents(app, i)
                        Assert.StartsWith("é€ß²µ§àçù", shown, StringComparison.Ordinal)
                        Assert.Contains("éèàçù", shown, StringComparison.Ordinal)
                    Next
                    ' Bad input is a message, never a crash.
                    Dim from = app.Mark()
                    app.Click("add-circle")
                    app.WaitFor("^message: Please enter a suitable value for the mass and radius! radius \(m\) 'é€ß", skip:=from)
                    ' A file name with accents, typed into the Save dialog, then into the Open dialog.
                    Dim name = "démo-" & round & "-é€ß.json"
                    Dim path = IO.Path.Combine(folder, name)
                    app.ClickForDialog("save", "Save the scene")
                    from = app.Mark()
                    app.TypeAndEnter(path)
                    app.WaitFor("^saved " & name & ": ", skip:=from)
                    Assert.True(IO.File.Exists(path), "no file " & path)
                    app.ClickForDialog("open", "Open a scene")
                    from = app.Mark()
                    app.TypeAndEnter(path)
                    app.WaitFor("^opened " & name & ": ", skip:=from)
                Next
                Assert.True(app.X.AppIsRunning, app.X.AppOutput())
                Assert.DoesNotContain("SIGSEGV", app.X.AppOutput(), StringComparison.Ordinal)
            End Using
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub
End Class
