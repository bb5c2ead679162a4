Option Strict On
Imports System.IO
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Files written whole or not at all (saved scenes, exported tables and pictures): a failure leaves an
''' existing file as it was and no temporary file behind, and its message names the folder, never the
''' temporary file.
''' </summary>
Public Class WholeFileTests
    Inherits TempFolderTests

    Public Sub New()
        MyBase.New("whole-file-")
    End Sub

    <Fact>
    Public Sub AFailedWrite_LeavesTheOldFileAndNoTemporary()
        Dim target = Path.Combine(Folder, "series.csv")
        WholeFile.Write(target, Sub(s) s.Write({65, 66}, 0, 2))
        Assert.Equal("AB", File.ReadAllText(target))
        ' A writer that fails half-way: the old file stays as it was, and nothing else is left.
        Assert.ThrowsAny(Of InvalidOperationException)(
            Sub() WholeFile.Write(target, Sub(s)
                                               s.Write({67}, 0, 1)
                                               Throw New InvalidOperationException("disk gone")
                                           End Sub))
        Assert.Equal("AB", File.ReadAllText(target))
        Assert.Single(Directory.GetFiles(Folder))
    End Sub

    <Fact>
    Public Sub AFailedWrite_OfANewFile_LeavesNothing()
        Dim target = Path.Combine(Folder, "picture.png")
        Assert.ThrowsAny(Of InvalidOperationException)(
            Sub() WholeFile.Write(target, Sub(s)
                                               s.WriteByte(1)
                                               Throw New InvalidOperationException("encoder gone")
                                           End Sub))
        Assert.Empty(Directory.GetFileSystemEntries(Folder))
    End Sub

    <Fact>
    Public Sub ASecondWrite_ReplacesTheFirst_Whole()
        Dim target = Path.Combine(Folder, "scene.json")
        WholeFile.Write(target, Sub(s) s.Write({65, 66, 67, 68, 69, 70}, 0, 6))
        WholeFile.Write(target, Sub(s) s.Write({71, 72}, 0, 2))
        Assert.Equal("GH", File.ReadAllText(target))
        Assert.Single(Directory.GetFiles(Folder))
    End Sub

    <Fact>
    Public Sub IntoAMissingFolder_TheMessageNamesIt_AndNothingIsWritten()
        Dim missing = Path.Combine(Folder, "nowhere", "x.csv")
        Dim ex = Assert.Throws(Of IOException)(Sub() WholeFile.Write(missing, Sub(s) s.WriteByte(1)))
        Assert.Contains("nowhere", ex.Message, StringComparison.Ordinal)
        Assert.Contains("nothing was written", ex.Message, StringComparison.Ordinal)
        Assert.Empty(Directory.GetFileSystemEntries(Folder))
    End Sub

    <Fact>
    Public Sub OverAFolderOfTheSameName_TheMessageNamesTheFolder_NotTheTemporaryFile_AndTheFolderIsKept()
        Dim target = Path.Combine(Folder, "taken")
        Directory.CreateDirectory(target)
        File.WriteAllText(Path.Combine(target, "inside.txt"), "kept")
        Dim ex = Assert.Throws(Of IOException)(Sub() WholeFile.Write(target, Sub(s) s.WriteByte(1)))
        Assert.Contains(Folder, ex.Message, StringComparison.Ordinal)
        Assert.Contains("nothing was written", ex.Message, StringComparison.Ordinal)
        Assert.DoesNotContain(".tmp", ex.Message, StringComparison.Ordinal)
        Assert.Equal("kept", File.ReadAllText(Path.Combine(target, "inside.txt")))
        Assert.Equal({target}, Directory.GetFileSystemEntries(Folder))
    End Sub

    <Fact>
    Public Sub ANameNoFileCanHave_IsRefusedInPlainWords()
        Dim bad = Folder & Path.DirectorySeparatorChar & "a" & ChrW(0) & "b.csv"
        Dim ex = Assert.Throws(Of IOException)(Sub() WholeFile.Write(bad, Sub(s) s.WriteByte(1)))
        Assert.Contains("is not a file name this computer accepts", ex.Message, StringComparison.Ordinal)
        Assert.Empty(Directory.GetFileSystemEntries(Folder))
    End Sub
End Class
