Option Strict On
Imports System.Globalization
Imports System.Text

''' <summary>
''' Log–log plots as plain SVG text, written without any plotting package: axes with decade ticks and
''' labels, one polyline with markers per series, a legend. Used for the work-precision plots (error
''' against cost) and the scaling plot.
''' </summary>
Friend Module SvgPlot
    Private Const Width As Double = 760
    Private Const Height As Double = 480
    Private Const Left As Double = 90
    Private Const Right As Double = 190
    Private Const Top As Double = 48
    Private Const Bottom As Double = 64
    Private Const Margin As Double = 0.25

    ''' <summary>
    ''' Values at or below this are drawn at it, so an exact result (error 0) still appears on a log
    ''' axis; the plot says so in a footnote.
    ''' </summary>
    Public Const LogFloor As Double = 1.0E-16

    ''' <summary>Renders the plot. Points that are NaN or infinite are left out; values ≤ <see cref="LogFloor"/> are drawn at it.</summary>
    Public Function Render(title As String, xLabel As String, yLabel As String, series As IReadOnlyList(Of PlotSeries)) As String
        If series Is Nothing Then Throw New ArgumentNullException(NameOf(series))
        Dim drawn = series.Select(Function(s) New PlotSeries(s.Name, s.Color, s.Points.Where(Function(p) IsDrawable(p.X) AndAlso IsDrawable(p.Y)).
                                  Select(Function(p) New PlotPoint(Math.Max(p.X, LogFloor), Math.Max(p.Y, LogFloor), p.Label)), s.Marker)).ToList()
        Dim clamped = series.Any(Function(s) s.Points.Any(Function(p) IsDrawable(p.X) AndAlso IsDrawable(p.Y) AndAlso (p.X <= LogFloor OrElse p.Y <= LogFloor)))
        Dim all = drawn.SelectMany(Function(s) s.Points).ToList()
        Dim xr = DecadeRange(all.Select(Function(p) p.X))
        Dim yr = DecadeRange(all.Select(Function(p) p.Y))

        Dim plotW = Width - Left - Right
        Dim plotH = Height - Top - Bottom
        ' A quarter of a decade of margin inside the frame, so no marker sits on an edge.
        Dim xLo = xr.Lo - Margin, xHi = xr.Hi + Margin, yLo = yr.Lo - Margin, yHi = yr.Hi + Margin
        Dim px = Function(x As Double) Left + (Math.Log10(x) - xLo) / (xHi - xLo) * plotW
        Dim py = Function(y As Double) Top + plotH - (Math.Log10(y) - yLo) / (yHi - yLo) * plotH

        Dim sb As New StringBuilder
        sb.Append("<svg xmlns=""http://www.w3.org/2000/svg"" width=""").Append(N(Width)).Append(""" height=""").Append(N(Height)).
           Append(""" viewBox=""0 0 ").Append(N(Width)).Append(" "c).Append(N(Height)).Append(""" font-family=""DejaVu Sans, Arial, sans-serif"" font-size=""12"">").Append(ControlChars.Lf)
        sb.Append("<rect width=""100%"" height=""100%"" fill=""white""/>").Append(ControlChars.Lf)
        sb.Append("<text x=""").Append(N(Width / 2)).Append(""" y=""24"" text-anchor=""middle"" font-size=""15"" font-weight=""bold"">").Append(Escape(title)).Append("</text>").Append(ControlChars.Lf)

        ' Grid and ticks, one per decade (every other decade when there are many).
        Dim xEvery = If(xr.Hi - xr.Lo > 10, 2, 1)
        For d = xr.Lo To xr.Hi Step xEvery
            Dim x = px(Math.Pow(10, d))
            Line(sb, x, Top, x, Top + plotH, "#e0e0e0")
            sb.Append("<text x=""").Append(N(x)).Append(""" y=""").Append(N(Top + plotH + 18)).Append(""" text-anchor=""middle"">").Append(Decade(d)).Append("</text>").Append(ControlChars.Lf)
        Next
        Dim yEvery = If(yr.Hi - yr.Lo > 10, 2, 1)
        For d = yr.Lo To yr.Hi Step yEvery
            Dim y = py(Math.Pow(10, d))
            Line(sb, Left, y, Left + plotW, y, "#e0e0e0")
            sb.Append("<text x=""").Append(N(Left - 8)).Append(""" y=""").Append(N(y + 4)).Append(""" text-anchor=""end"">").Append(Decade(d)).Append("</text>").Append(ControlChars.Lf)
        Next
        sb.Append("<rect x=""").Append(N(Left)).Append(""" y=""").Append(N(Top)).Append(""" width=""").Append(N(plotW)).Append(""" height=""").Append(N(plotH)).
           Append(""" fill=""none"" stroke=""#333""/>").Append(ControlChars.Lf)
        sb.Append("<text x=""").Append(N(Left + plotW / 2)).Append(""" y=""").Append(N(Height - 22)).Append(""" text-anchor=""middle"">").Append(Escape(xLabel)).Append("</text>").Append(ControlChars.Lf)
        sb.Append("<text transform=""translate(20,").Append(N(Top + plotH / 2)).Append(") rotate(-90)"" text-anchor=""middle"">").Append(Escape(yLabel)).Append("</text>").Append(ControlChars.Lf)

        ' Series: a line through the points in order, a marker and a small label at each point.
        For k = 0 To drawn.Count - 1
            Dim s = drawn(k)
            If s.Points.Count >= 2 Then
                sb.Append("<polyline class=""series"" fill=""none"" stroke=""").Append(s.Color).Append(""" stroke-width=""2"" points=""")
                sb.Append(String.Join(" ", s.Points.Select(Function(p) N(px(p.X)) & "," & N(py(p.Y)))))
                sb.Append("""/>").Append(ControlChars.Lf)
            End If
            For Each p In s.Points
                Marker(sb, s.Marker, px(p.X), py(p.Y), s.Color, If(s.Points.Count = 1, 7.0, 4.0))
                If p.Label.Length > 0 Then
                    sb.Append("<text x=""").Append(N(px(p.X) + 7)).Append(""" y=""").Append(N(py(p.Y) - 6)).Append(""" font-size=""10"" fill=""").
                       Append(s.Color).Append(""">").Append(Escape(p.Label)).Append("</text>").Append(ControlChars.Lf)
                End If
            Next
        Next

        ' Legend, to the right of the plot.
        Dim lx = Left + plotW + 18
        For k = 0 To series.Count - 1
            Dim ly = Top + 12 + k * 22
            Marker(sb, series(k).Marker, lx + 8, ly, series(k).Color, 5)
            If series(k).Points.Count <> 1 Then Line(sb, lx - 2, ly, lx + 18, ly, series(k).Color)
            sb.Append("<text x=""").Append(N(lx + 26)).Append(""" y=""").Append(N(ly + 4)).Append(""">").Append(Escape(series(k).Name)).Append("</text>").Append(ControlChars.Lf)
        Next
        If clamped Then
            sb.Append("<text x=""").Append(N(Left)).Append(""" y=""").Append(N(Height - 6)).Append(""" font-size=""10"" fill=""#555"">").
               Append(Escape("values at or below 1e-16 (exact to rounding) are drawn at 1e-16")).Append("</text>").Append(ControlChars.Lf)
        End If
        If all.Count = 0 Then
            sb.Append("<text x=""").Append(N(Left + plotW / 2)).Append(""" y=""").Append(N(Top + plotH / 2)).Append(""" text-anchor=""middle"">no data</text>").Append(ControlChars.Lf)
        End If
        sb.Append("</svg>").Append(ControlChars.Lf)
        Return sb.ToString()
    End Function

    Private Function IsDrawable(v As Double) As Boolean
        Return Not Double.IsNaN(v) AndAlso Not Double.IsInfinity(v) AndAlso v >= 0
    End Function

    ''' <summary>Whole decades (log10) that contain every value, at least one decade wide.</summary>
    Friend Function DecadeRange(values As IEnumerable(Of Double)) As (Lo As Integer, Hi As Integer)
        Dim logs = values.Where(Function(v) v > 0).Select(Function(v) Math.Log10(v)).ToList()
        If logs.Count = 0 Then Return (0, 1)
        Dim lo = CInt(Math.Floor(logs.Min() + 1.0E-9))
        Dim hi = CInt(Math.Ceiling(logs.Max() - 1.0E-9))
        If hi <= lo Then hi = lo + 1
        Return (lo, hi)
    End Function

    Private Sub Marker(sb As StringBuilder, index As Integer, x As Double, y As Double, color As String, size As Double)
        Select Case index Mod 3
            Case 0 ' diamond
                sb.Append("<polygon class=""marker"" fill=""").Append(color).Append(""" points=""").
                   Append(N(x)).Append(","c).Append(N(y - size)).Append(" "c).Append(N(x + size)).Append(","c).Append(N(y)).Append(" "c).
                   Append(N(x)).Append(","c).Append(N(y + size)).Append(" "c).Append(N(x - size)).Append(","c).Append(N(y)).Append("""/>").Append(ControlChars.Lf)
            Case 1 ' circle
                sb.Append("<circle class=""marker"" fill=""").Append(color).Append(""" cx=""").Append(N(x)).Append(""" cy=""").Append(N(y)).
                   Append(""" r=""").Append(N(size * 0.8)).Append("""/>").Append(ControlChars.Lf)
            Case Else ' square
                sb.Append("<rect class=""marker"" fill=""").Append(color).Append(""" x=""").Append(N(x - size * 0.7)).Append(""" y=""").Append(N(y - size * 0.7)).
                   Append(""" width=""").Append(N(size * 1.4)).Append(""" height=""").Append(N(size * 1.4)).Append("""/>").Append(ControlChars.Lf)
        End Select
    End Sub

    Private Sub Line(sb As StringBuilder, x1 As Double, y1 As Double, x2 As Double, y2 As Double, color As String)
        sb.Append("<line x1=""").Append(N(x1)).Append(""" y1=""").Append(N(y1)).Append(""" x2=""").Append(N(x2)).Append(""" y2=""").Append(N(y2)).
           Append(""" stroke=""").Append(color).Append("""/>").Append(ControlChars.Lf)
    End Sub

    ''' <summary>"1e-6", "1", "10", "1e4": short decade labels.</summary>
    Friend Function Decade(d As Integer) As String
        Select Case d
            Case 0 : Return "1"
            Case 1 : Return "10"
            Case 2 : Return "100"
            Case Else : Return "1e" & d.ToString(CultureInfo.InvariantCulture)
        End Select
    End Function

    Private Function N(v As Double) As String
        Return v.ToString("0.##", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>Text made safe for an SVG (XML) document.</summary>
    Friend Function Escape(text As String) As String
        If text Is Nothing Then Return ""
        Return text.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal).
            Replace(">", "&gt;", StringComparison.Ordinal).Replace("""", "&quot;", StringComparison.Ordinal)
    End Function
End Module
