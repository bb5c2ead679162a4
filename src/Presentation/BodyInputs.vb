Option Strict On

''' <summary>
''' The text in the window's input boxes, exactly as the teacher typed it: the window passes every
''' edit here, so nothing the presenter does (pause, reset, add, open) can put an older value back.
''' The presenter changes a text only when it says so in a message (a value brought to a limit) or
''' when a scene with another container is opened, and then asks the window to show the inputs.
''' </summary>
Public NotInheritable Class BodyInputs
    Private ReadOnly _texts As New Dictionary(Of InputField, String) From {
        {InputField.Radius, "0.25"}, {InputField.Mass, "1"},
        {InputField.RectangleWidth, "1"}, {InputField.RectangleHeight, "0.5"},
        {InputField.ContainerWidth, ""}, {InputField.ContainerHeight, ""},
        {InputField.Sides, "5"}, {InputField.PolygonAngle, "0"}, {InputField.Stiffness, "20"},
        {InputField.FrictionKinetic, "0"}, {InputField.FrictionStatic, ""}, {InputField.LiquidDensity, "1000"}}

    ''' <summary>The text of one box.</summary>
    Default Public Property Item(field As InputField) As String
        Get
            Return _texts(field)
        End Get
        Set(value As String)
            If Not _texts.ContainsKey(field) Then Throw New ArgumentOutOfRangeException(NameOf(field))
            _texts(field) = If(value, "")
        End Set
    End Property

    ''' <summary>Circle radius, and a regular polygon's size (centre to corner), m.</summary>
    Public Property RadiusText As String
        Get
            Return Item(InputField.Radius)
        End Get
        Set(value As String)
            Item(InputField.Radius) = value
        End Set
    End Property

    ''' <summary>Circle mass, kg.</summary>
    Public Property MassText As String
        Get
            Return Item(InputField.Mass)
        End Get
        Set(value As String)
            Item(InputField.Mass) = value
        End Set
    End Property

    ''' <summary>Whether the next circle or polygon is fixed.</summary>
    Public Property IsFixed As Boolean

    ''' <summary>Whether the next rectangle is a fixed obstacle (ticked) or a movable box with the typed mass.</summary>
    Public Property RectangleFixed As Boolean = True

    ''' <summary>Rectangle width, m.</summary>
    Public Property WidthText As String
        Get
            Return Item(InputField.RectangleWidth)
        End Get
        Set(value As String)
            Item(InputField.RectangleWidth) = value
        End Set
    End Property

    ''' <summary>Rectangle height, m.</summary>
    Public Property HeightText As String
        Get
            Return Item(InputField.RectangleHeight)
        End Get
        Set(value As String)
            Item(InputField.RectangleHeight) = value
        End Set
    End Property

    ''' <summary>A regular polygon's number of sides.</summary>
    Public Property SidesText As String
        Get
            Return Item(InputField.Sides)
        End Get
        Set(value As String)
            Item(InputField.Sides) = value
        End Set
    End Property

    ''' <summary>A regular polygon's turn, degrees anticlockwise.</summary>
    Public Property PolygonAngleText As String
        Get
            Return Item(InputField.PolygonAngle)
        End Get
        Set(value As String)
            Item(InputField.PolygonAngle) = value
        End Set
    End Property

    ''' <summary>A spring's stiffness, N/m.</summary>
    Public Property StiffnessText As String
        Get
            Return Item(InputField.Stiffness)
        End Get
        Set(value As String)
            Item(InputField.Stiffness) = value
        End Set
    End Property

    ''' <summary>Container width, m.</summary>
    Public Property ContainerWidthText As String
        Get
            Return Item(InputField.ContainerWidth)
        End Get
        Set(value As String)
            Item(InputField.ContainerWidth) = value
        End Set
    End Property

    ''' <summary>Container height, m.</summary>
    Public Property ContainerHeightText As String
        Get
            Return Item(InputField.ContainerHeight)
        End Get
        Set(value As String)
            Item(InputField.ContainerHeight) = value
        End Set
    End Property

    ''' <summary>The world's μk (kinetic friction).</summary>
    Public Property FrictionText As String
        Get
            Return Item(InputField.FrictionKinetic)
        End Get
        Set(value As String)
            Item(InputField.FrictionKinetic) = value
        End Set
    End Property

    ''' <summary>The world's μs (static friction); empty for the same as μk.</summary>
    Public Property StaticFrictionText As String
        Get
            Return Item(InputField.FrictionStatic)
        End Get
        Set(value As String)
            Item(InputField.FrictionStatic) = value
        End Set
    End Property
End Class
