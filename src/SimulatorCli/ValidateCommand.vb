Option Strict On

''' <summary>validate SCENE: prints "ok" and exits 0, or names the place and the problem and exits 2.</summary>
Friend Module ValidateCommand
    Friend Function Execute(args As IReadOnlyList(Of String)) As Integer
        If args.Count = 0 Then Throw New BadInputException("validate: no scene file given (usage: validate SCENE)")
        For Each a In args
            If a.StartsWith("-"c) AndAlso a.Length > 1 Then Throw New BadInputException("validate: unknown option '" & a & "' (usage: validate SCENE)")
        Next
        If args.Count > 1 Then Throw New BadInputException("validate: unexpected argument '" & args(1) & "' (usage: validate SCENE)")
        SceneInput.Load(args(0))
        Console.Out.WriteLine("ok")
        Return ExitCodes.Ok
    End Function
End Module
