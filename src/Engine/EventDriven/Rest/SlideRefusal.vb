Option Strict On

''' <summary>Why a body did not start sliding round a corner (see <see cref="CornerSlides.Start"/>).</summary>
Friend Enum SlideRefusal
    ''' <summary>It started sliding.</summary>
    None
    ''' <summary>No gravity, or at rest exactly on top: nothing pulls it round.</summary>
    Still
    ''' <summary>Too fast to follow the curve at all: it flies off at once.</summary>
    FliesOff
    ''' <summary>A moving neighbour touches it, or nearly (within 10⁻³ of its size): a slide would be cut short at once.</summary>
    Crowded
    ''' <summary>A wall or another fixed body lies within the slide's reach, which a slide does not check.</summary>
    Blocked
End Enum
