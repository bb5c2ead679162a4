Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Runtime.InteropServices

''' <summary>What the numbers were measured on: a timing means nothing without it.</summary>
Friend NotInheritable Class MachineInfo
    ''' <summary>UTC date and time of the run, "yyyy-MM-dd HH:mm UTC".</summary>
    Public Property [Date] As String = ""
    ''' <summary>CPU model from /proc/cpuinfo, or "unknown".</summary>
    Public Property CpuModel As String = "unknown"
    ''' <summary>Logical cores the process may use.</summary>
    Public Property Cores As Integer
    ''' <summary>Physical memory, GB.</summary>
    Public Property MemoryGigabytes As Double
    ''' <summary>Operating system description.</summary>
    Public Property OperatingSystem As String = ""
    ''' <summary>.NET runtime description, e.g. ".NET 10.0.0".</summary>
    Public Property DotNet As String = ""

    ''' <summary>This machine, now.</summary>
    Public Shared Function Current() As MachineInfo
        Dim m As New MachineInfo With {
            .Date = DateTime.UtcNow.ToString("yyyy-MM-dd HH:mm", CultureInfo.InvariantCulture) & " UTC",
            .Cores = Environment.ProcessorCount,
            .OperatingSystem = RuntimeInformation.OSDescription,
            .DotNet = RuntimeInformation.FrameworkDescription}
        m.CpuModel = If(ReadCpuModel("/proc/cpuinfo"), "unknown")
        Dim kb = ReadMemTotalKilobytes("/proc/meminfo")
        m.MemoryGigabytes = If(kb > 0, kb / 1024.0 / 1024.0, GC.GetGCMemoryInfo().TotalAvailableMemoryBytes / 1024.0 ^ 3)
        Return m
    End Function

    ''' <summary>The first "model name" in a cpuinfo file, or Nothing.</summary>
    Friend Shared Function ReadCpuModel(path As String) As String
        If Not File.Exists(path) Then Return Nothing
        For Each line In File.ReadLines(path)
            If line.StartsWith("model name", StringComparison.Ordinal) Then
                Dim colon = line.IndexOf(":"c)
                If colon >= 0 Then Return line.Substring(colon + 1).Trim()
            End If
        Next
        Return Nothing
    End Function

    Private Shared Function ReadMemTotalKilobytes(path As String) As Double
        If Not File.Exists(path) Then Return 0
        For Each line In File.ReadLines(path)
            If line.StartsWith("MemTotal:", StringComparison.Ordinal) Then
                Dim parts = line.Split(" "c, StringSplitOptions.RemoveEmptyEntries)
                Dim kb As Double
                If parts.Length >= 2 AndAlso Double.TryParse(parts(1), NumberStyles.Float, CultureInfo.InvariantCulture, kb) Then Return kb
            End If
        Next
        Return 0
    End Function

    ''' <summary>"2 cores, Intel(R) …, 23.5 GB RAM, .NET 10.0.0, Linux …".</summary>
    Public Overrides Function ToString() As String
        Return Cores.ToString(CultureInfo.InvariantCulture) & " cores, " & CpuModel & ", " &
               MemoryGigabytes.ToString("0.0", CultureInfo.InvariantCulture) & " GB RAM, " & DotNet & ", " & OperatingSystem
    End Function
End Class
