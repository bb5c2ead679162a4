Option Strict On

''' <summary>
''' A scene whose report says how many times faster than real time it runs: from the median of the
''' timed runs (after the warm-up, as the app runs once its first seconds have compiled the code),
''' not from the first run, which also pays for compiling.
''' </summary>
Friend Interface IRealTimeScene
End Interface
