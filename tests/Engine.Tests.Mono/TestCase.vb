Option Strict On
Imports System.Globalization
Imports System.Reflection
Imports System.Threading.Tasks
Imports Xunit
Imports Xunit.Sdk

Namespace Mono
    ''' <summary>
    ''' One test to run: a [Fact] method, or a [Theory] method with one row of its data. Only what the
    ''' engine's tests use: public classes, a constructor with no parameters or one
    ''' <see cref="Abstractions.ITestOutputHelper"/>, IDisposable, InlineData and MemberData, and
    ''' methods that return a Task.
    ''' </summary>
    Friend NotInheritable Class TestCase
        Private ReadOnly _method As MethodInfo
        Private ReadOnly _arguments As Object()
        ''' <summary>Why the test cannot even start (a theory without data), or Nothing.</summary>
        Private ReadOnly _problem As String

        Private Sub New(method As MethodInfo, arguments As Object(), skipReason As String, Optional problem As String = Nothing)
            _method = method
            _arguments = arguments
            _problem = problem
            Me.SkipReason = skipReason
            Dim shown = If(arguments Is Nothing, "", "(" & String.Join(", ", arguments.Select(AddressOf Show)) & ")")
            Name = method.DeclaringType.Name & "." & method.Name & shown
        End Sub

        ''' <summary>The test's class: tests of one class run one after another, as xunit runs them.</summary>
        Public ReadOnly Property TestClass As Type
            Get
                Return _method.DeclaringType
            End Get
        End Property

        ''' <summary>Class.Method, with the theory row's arguments in parentheses.</summary>
        Public ReadOnly Property Name As String

        ''' <summary>Why the test is not run (its Skip text, or a reason given here), or Nothing.</summary>
        Public ReadOnly Property SkipReason As String

        ''' <summary>Every test in the assembly, in a stable order (class, then method name, then row).</summary>
        Public Shared Function Discover(assembly As Assembly) As List(Of TestCase)
            Dim found As New List(Of TestCase)()
            Dim classes = assembly.GetTypes().Where(Function(t) t.IsPublic AndAlso t.IsClass AndAlso Not t.IsAbstract).OrderBy(Function(t) t.FullName, StringComparer.Ordinal)
            For Each type In classes
                Dim methods = type.GetMethods(BindingFlags.Public Or BindingFlags.Instance Or BindingFlags.Static).OrderBy(Function(m) m.Name, StringComparer.Ordinal)
                For Each method In methods
                    Dim fact = method.GetCustomAttribute(Of FactAttribute)()
                    If fact Is Nothing Then Continue For
                    If TypeOf fact IsNot TheoryAttribute Then
                        found.Add(New TestCase(method, Nothing, fact.Skip))
                        Continue For
                    End If
                    Dim rows = 0
                    For Each source In method.GetCustomAttributes(Of DataAttribute)()
                        For Each row In source.GetData(method)
                            found.Add(New TestCase(method, Convert(method, row), If(fact.Skip, source.Skip)))
                            rows += 1
                        Next
                    Next
                    ' xunit fails a theory without data rather than pass it by running nothing.
                    If rows = 0 Then found.Add(New TestCase(method, Nothing, fact.Skip, "the theory has no data"))
                Next
            Next
            Return found
        End Function

        ''' <summary>Runs the test on a fresh instance of its class; returns what it threw, or Nothing when it passed.</summary>
        Public Function Run(output As Abstractions.ITestOutputHelper) As Exception
            Dim instance As Object = Nothing
            If _problem IsNot Nothing Then Return New InvalidOperationException(_problem)
            Try
                If Not _method.IsStatic Then instance = Create(_method.DeclaringType, output)
                Dim result = _method.Invoke(instance, _arguments)
                TryCast(result, Task)?.GetAwaiter().GetResult()
                Return Nothing
            Catch ex As TargetInvocationException When ex.InnerException IsNot Nothing
                Return ex.InnerException
            Catch ex As Exception
                Return ex
            Finally
                TryCast(instance, IDisposable)?.Dispose()
            End Try
        End Function

        Private Shared Function Create(type As Type, output As Abstractions.ITestOutputHelper) As Object
            Dim withOutput = type.GetConstructor({GetType(Abstractions.ITestOutputHelper)})
            If withOutput IsNot Nothing Then Return withOutput.Invoke({output})
            Return Activator.CreateInstance(type)
        End Function

        ''' <summary>A data row fitted to the parameters, as xunit does: missing optional ones take their defaults, numbers are converted.</summary>
        Private Shared Function Convert(method As MethodInfo, row As Object()) As Object()
            Dim parameters = method.GetParameters()
            Dim args(parameters.Length - 1) As Object
            For k = 0 To parameters.Length - 1
                Dim p = parameters(k)
                If k >= row.Length Then
                    If Not p.IsOptional Then Throw New InvalidOperationException($"{method.DeclaringType.Name}.{method.Name}: a data row has {row.Length} values for {parameters.Length} parameters")
                    args(k) = p.DefaultValue
                ElseIf row(k) IsNot Nothing AndAlso Not p.ParameterType.IsInstanceOfType(row(k)) AndAlso TypeOf row(k) Is IConvertible Then
                    args(k) = System.Convert.ChangeType(row(k), p.ParameterType, CultureInfo.InvariantCulture)
                Else
                    args(k) = row(k)
                End If
            Next
            Return args
        End Function

        Private Shared Function Show(value As Object) As String
            If value Is Nothing Then Return "null"
            If TypeOf value Is String Then Return """" & CStr(value) & """"
            If TypeOf value Is Double Then Return CDbl(value).ToString("R", CultureInfo.InvariantCulture)
            Return System.Convert.ToString(value, CultureInfo.InvariantCulture)
        End Function
    End Class
End Namespace
