Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Text

''' <summary>
''' The Scenes menu's list: every scene file (*.json) in the scenes folder, titled and described by
''' the folder's index, lessons.txt. The scene format has no title, and a teacher who drops a new
''' file into the folder should see it in the menu without writing an index line, so the index
''' orders and names the files it lists and every other file follows, titled from its name.
''' </summary>
Public Module LessonIndex
    ''' <summary>The index's file name in the scenes folder.</summary>
    Public Const IndexFileName As String = "lessons.txt"

    Private ReadOnly Bar As Char() = {"|"c}
    Private ReadOnly LineFeed As Char() = {ChrW(10)}

    ''' <summary>
    ''' The lessons in <paramref name="folder"/>, in menu order; none when the folder is missing or
    ''' cannot be read. An index that cannot be read is treated as absent (every file still shows).
    ''' </summary>
    Public Function Read(folder As String) As IReadOnlyList(Of Lesson)
        Dim files As String()
        Try
            If String.IsNullOrEmpty(folder) OrElse Not Directory.Exists(folder) Then Return Array.Empty(Of Lesson)()
            files = Directory.GetFiles(folder, "*.json")
        Catch ex As Exception When TypeOf ex Is IOException OrElse TypeOf ex Is UnauthorizedAccessException OrElse TypeOf ex Is ArgumentException OrElse TypeOf ex Is NotSupportedException
            Return Array.Empty(Of Lesson)()
        End Try
        Dim index = ""
        Try
            Dim indexPath = Path.Combine(folder, IndexFileName)
            If File.Exists(indexPath) Then index = File.ReadAllText(indexPath, Encoding.UTF8)
        Catch ex As Exception When TypeOf ex Is IOException OrElse TypeOf ex Is UnauthorizedAccessException OrElse TypeOf ex Is NotSupportedException
            index = ""
        End Try
        Dim names = files.Select(Function(f) Path.GetFileName(f)).ToList()
        Return Parse(index, names).Select(Function(e) New Lesson(Path.Combine(folder, e.FileName), e.Title, e.Summary)).ToList()
    End Function

    ''' <summary>
    ''' The menu's entries for the scene files <paramref name="fileNames"/> and the index's text: the
    ''' files the index lists, in its order, with its titles and lines; then every other file, by
    ''' name, titled from its name with no line. An index line names a file, a title and what it
    ''' shows, separated by "|"; lines starting with # and blank lines are skipped, a line naming a
    ''' file that is not there (or one already listed) is skipped, and a line without a title gets
    ''' the title from the file's name.
    ''' </summary>
    Public Function Parse(indexText As String, fileNames As IEnumerable(Of String)) As IReadOnlyList(Of (FileName As String, Title As String, Summary As String))
        If fileNames Is Nothing Then Throw New ArgumentNullException(NameOf(fileNames))
        Dim present As New HashSet(Of String)(fileNames, StringComparer.Ordinal)
        Dim result As New List(Of (FileName As String, Title As String, Summary As String))
        Dim listed As New HashSet(Of String)(StringComparer.Ordinal)
        For Each raw In If(indexText, "").Split(LineFeed, StringSplitOptions.None)
            Dim line = raw.Trim()
            If line.Length = 0 OrElse line(0) = "#"c Then Continue For
            Dim parts = line.Split(Bar, 3)
            Dim name = parts(0).Trim()
            If Not present.Contains(name) OrElse Not listed.Add(name) Then Continue For
            Dim title = If(parts.Length > 1, parts(1).Trim(), "")
            Dim summary = If(parts.Length > 2, parts(2).Trim(), "")
            result.Add((name, If(title.Length = 0, TitleFromFileName(name), title), summary))
        Next
        For Each name In present.Where(Function(n) Not listed.Contains(n)).OrderBy(Function(n) n, StringComparer.OrdinalIgnoreCase)
            result.Add((name, TitleFromFileName(name), ""))
        Next
        Return result
    End Function

    ''' <summary>"peg-board.json" → "Peg board": the name without its extension, dashes and underscores as spaces, a capital first letter.</summary>
    Public Function TitleFromFileName(fileName As String) As String
        Dim stem = Path.GetFileNameWithoutExtension(If(fileName, "")).Replace("-"c, " "c).Replace("_"c, " "c).Trim()
        Do While stem.Contains("  ")
            stem = stem.Replace("  ", " ")
        Loop
        If stem.Length = 0 Then Return If(fileName, "")
        Return Char.ToUpper(stem(0), CultureInfo.InvariantCulture) & stem.Substring(1)
    End Function
End Module
