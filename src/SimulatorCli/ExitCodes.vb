Option Strict On

''' <summary>The exit statuses of cli.md.</summary>
Friend Module ExitCodes
    Friend Const Ok As Integer = 0
    Friend Const Failure As Integer = 1
    Friend Const BadInput As Integer = 2
End Module
