Option Strict On
Imports System.Drawing
Imports System.Globalization
Imports System.Runtime.InteropServices

''' <summary>
''' The screen's dots per inch, and how much to scale the window by. On Windows the runtime knows
''' (the manifest declares the app DPI-aware, so GDI+ reports the real DPI and draws points at it).
''' Under Mono on X11 a window laid out in pixels with 10-point fonts comes out tiny on a 192-dpi
''' screen: Mono's GDI+ draws a point at 96 dpi whatever it reports (it reports Xft.dpi when that is
''' set, 96 otherwise). There the DPI is read from X itself, first the Xft.dpi resource (what GNOME,
''' KDE and Xfce set for the user's scale), else the screen's size in millimetres, and fonts are
''' scaled from 96.
''' </summary>
Friend NotInheritable Class ScreenDpi
    Private Sub New(screen As Double, graphics As Double, source As String)
        Me.Screen = screen
        Me.Graphics = graphics
        Me.Source = source
    End Sub

    ''' <summary>The screen's DPI.</summary>
    Public ReadOnly Property Screen As Double
    ''' <summary>The DPI GDI+ draws points at (96 under Mono whatever the screen or what it reports).</summary>
    Public ReadOnly Property Graphics As Double
    ''' <summary>Where <see cref="Screen"/> came from, for the trace.</summary>
    Public ReadOnly Property Source As String

    ''' <summary>Screen pixels per 96-dpi pixel: how much every size in the layout grows.</summary>
    Public ReadOnly Property Scale As Double
        Get
            Return Screen / 96.0
        End Get
    End Property

    ''' <summary>How much a font's point size must grow for GDI+ to draw it at the screen's DPI.</summary>
    Public ReadOnly Property FontScale As Double
        Get
            Return Screen / Graphics
        End Get
    End Property

    ''' <summary>Reads the DPI of the screen the app opens on.</summary>
    Public Shared Function Detect() As ScreenDpi
        Dim gdi = 96.0
        Using g = Drawing.Graphics.FromHwnd(IntPtr.Zero)
            gdi = g.DpiY
        End Using
        If Type.GetType("Mono.Runtime") Is Nothing OrElse Not RuntimeInformation.IsOSPlatform(OSPlatform.Linux) Then
            Return New ScreenDpi(gdi, gdi, "GDI+")
        End If
        Const monoPoints = 96.0
        Dim x = FromX11()
        If x.Dpi > 0 Then Return New ScreenDpi(Rounded(x.Dpi), monoPoints, x.Source)
        Return New ScreenDpi(monoPoints, monoPoints, "96 (X11 gave none)")
    End Function

    ''' <summary>To the nearest quarter of 96 dpi, between 96 and 384: a sloppy monitor size must not give 97.3 dpi.</summary>
    Private Shared Function Rounded(dpi As Double) As Double
        Dim quarter = Math.Round(dpi / 24.0) * 24.0
        Return Math.Max(96.0, Math.Min(384.0, quarter))
    End Function

    Private Shared ReadOnly Colon As Char() = {":"c}

    Private Shared Function FromX11() As (Dpi As Double, Source As String)
        Try
            Dim display = NativeMethods.XOpenDisplay(IntPtr.Zero)
            If display = IntPtr.Zero Then Return (0, "")
            Try
                Dim resources = NativeMethods.XResourceManagerString(display)
                If resources <> IntPtr.Zero Then
                    For Each line In If(Marshal.PtrToStringAnsi(resources), "").Split(ChrW(10))
                        Dim parts = line.Split(Colon, 2)
                        Dim value As Double
                        If parts.Length = 2 AndAlso parts(0).Trim() = "Xft.dpi" AndAlso
                           Double.TryParse(parts(1).Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, value) AndAlso value > 0 Then
                            Return (value, "Xft.dpi")
                        End If
                    Next
                End If
                Dim screen = NativeMethods.XDefaultScreen(display)
                Dim px = NativeMethods.XDisplayWidth(display, screen)
                Dim mm = NativeMethods.XDisplayWidthMM(display, screen)
                If px > 0 AndAlso mm > 0 Then Return (px * 25.4 / mm, "X screen size")
                Return (0, "")
            Finally
                ' Closing a connection opened a moment ago cannot fail in a way worth reporting.
                Dim unused = NativeMethods.XCloseDisplay(display)
            End Try
        Catch ex As DllNotFoundException
            Return (0, "")
        Catch ex As EntryPointNotFoundException
            Return (0, "")
        End Try
    End Function

    ''' <summary>The few Xlib calls needed (libX11 is there whenever Mono's WinForms runs on X11).</summary>
    Private NotInheritable Class NativeMethods
        Private Sub New()
        End Sub

        <DllImport("libX11")>
        Public Shared Function XOpenDisplay(name As IntPtr) As IntPtr
        End Function

        <DllImport("libX11")>
        Public Shared Function XCloseDisplay(display As IntPtr) As Integer
        End Function

        <DllImport("libX11")>
        Public Shared Function XResourceManagerString(display As IntPtr) As IntPtr
        End Function

        <DllImport("libX11")>
        Public Shared Function XDefaultScreen(display As IntPtr) As Integer
        End Function

        <DllImport("libX11")>
        Public Shared Function XDisplayWidth(display As IntPtr, screen As Integer) As Integer
        End Function

        <DllImport("libX11")>
        Public Shared Function XDisplayWidthMM(display As IntPtr, screen As Integer) As Integer
        End Function
    End Class
End Class
