Option Strict On
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Fuzzing.Workers

''' <summary>
''' Entry point. A campaign by default (see <see cref="FuzzOptions.Usage"/>); with --worker, a worker
''' process that checks the scenes a campaign sends it.
''' </summary>
Friend NotInheritable Class Program
    Private Sub New()
    End Sub

    Friend Shared Function Main(args As String()) As Integer
        If args Is Nothing Then Throw New ArgumentNullException(NameOf(args))
        If args.Length > 0 AndAlso args(0) = "--worker" Then
            Dim parent = 0
            If args.Length > 1 Then parent = Integer.Parse(args(1), Globalization.CultureInfo.InvariantCulture)
            Return WorkerLoop.Run(Console.In, Console.Out, parent)
        End If
        If args.Contains("--help") OrElse args.Contains("-h") Then
            Console.Out.WriteLine(FuzzOptions.Usage)
            Return 0
        End If
        Dim options As FuzzOptions
        Try
            options = FuzzOptions.Parse(args)
        Catch ex As ArgumentException
            Console.Error.WriteLine("fuzz: " & ex.Message)
            Return 2
        Catch ex As FormatException
            Console.Error.WriteLine("fuzz: " & ex.Message)
            Return 2
        End Try
        If options.Print Then
            For k = 0 To options.Scenes - 1
                Console.Out.Write(SceneGenerator.Generate(options.Seed + k, options.Kinds, options.MaxBodies, options.Rough).ToText())
            Next
            Return 0
        End If
        Dim result As CampaignResult
        Try
            result = Campaign.Run(options, Console.Out)
        Catch ex As IO.IOException
            Console.Error.WriteLine("fuzz: " & ex.Message)
            Return 2
        Catch ex As UnauthorizedAccessException
            Console.Error.WriteLine("fuzz: " & ex.Message)
            Return 2
        Catch ex As Text.Json.JsonException
            Console.Error.WriteLine("fuzz: " & options.SceneFile & " is not JSON: " & ex.Message)
            Return 2
        Catch ex As FormatException
            Console.Error.WriteLine("fuzz: " & options.SceneFile & ": " & ex.Message)
            Return 2
        End Try
        Return If(result.Failures().Count = 0, 0, 1)
    End Function
End Class
