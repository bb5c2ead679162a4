Option Strict On

''' <summary>Scenes with closed-form answers, as scene-file text.</summary>
Public Module TestScenes
    ''' <summary>' → ".</summary>
    Public Function Q(json As String) As String
        Return json.Replace("'"c, """"c)
    End Function

    ''' <summary>
    ''' g = 0, e = 1, no walls: "light" (1 kg, +2 m/s at x = 3) meets "heavy" (3 kg, −1 m/s at x = 7), radii 0.1 m.
    ''' They touch when the 3.8 m gap closes at 3 m/s, at t = 3.8/3 s; afterwards light −2.5 m/s, heavy +0.5 m/s.
    ''' </summary>
    Public ReadOnly Property HeadOn As String = Q("{'format':'physics-scene/1','world':{'width':10,'height':2,'gravity':0,'restitution':1,'walls':false},'bodies':[" &
        "{'id':'light','type':'circle','x':3,'y':1,'radius':0.1,'mass':1,'vx':2}," &
        "{'id':'peg','type':'circle','x':9,'y':1.8,'radius':0.1,'fixed':true}," &
        "{'id':'heavy','type':'circle','x':7,'y':1,'radius':0.1,'mass':3,'vx':-1}]}")

    ''' <summary>A ball dropped from rest 1 m above the floor (lowest point), g = 9.81, e = 0.9: it hits the floor at t = √(2/9.81) s.</summary>
    Public ReadOnly Property BouncingBall As String = Q("{'format':'physics-scene/1','world':{'width':1,'height':2.1,'gravity':9.81,'restitution':0.9},'bodies':[" &
        "{'id':'ball','type':'circle','x':0.5,'y':1.05,'radius':0.05,'mass':1}]}")
End Module
