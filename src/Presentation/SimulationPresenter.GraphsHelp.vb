Option Strict On

' What the help windows say about the Graphs tab and the Export menu (the tutorial's page) and the
' physics of the gas graphs (two pages of Maths used).
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>The tutorial's page on graphs and exports.</summary>
    Public Shared ReadOnly Property GraphsHelp As New HelpTopic("7. Graphs and data out",
        "The Graphs tab (beside the collision log) draws one graph: Energy (KE, PE and their sum against time), Momentum (px and py against time), Speeds (how many bodies have each speed, with the 2D Maxwell–Boltzmann curve for the gas's temperature) and Pressure (the push of the walls, measured from their impulses, beside the ideal gas law N·k·T/A). ⤢ Window shows the graph in a large window of its own for a projector." & vbLf & "" & vbLf &
        "The graphs show the run since the scene was opened, restarted or reset. A long run is kept whole at a coarser spacing, so memory never grows." & vbLf & "" & vbLf &
        "Export ▾ (beside Scenes) saves the Bodies table, the collision log or the graph's data as a CSV file a spreadsheet opens as it is, or the graph or the canvas as a PNG picture for a worksheet or a slide.")

    ''' <summary>The Maths used pages on the gas graphs.</summary>
    Public Shared ReadOnly Property GraphsMaths As IReadOnlyList(Of HelpTopic) = {
        New HelpTopic("Speeds in a gas: the 2D Maxwell–Boltzmann curve",
            "In a gas at temperature T each velocity component is spread like a normal distribution with variance kT/m. The bodies with speeds between v and v + dv lie in a ring of circumference 2πv in the (vₓ, v_y) plane, so the fraction per m/s is" & vbLf & "" & vbLf &
            "  f(v) = (m v / kT) · exp(−m v² / 2kT)" & vbLf & "" & vbLf &
            "Its area is 1, it peaks at v = √(kT/m), and its mean is √(πkT / 2m). A body moving in a plane (and not spinning) has two degrees of freedom, ½kT each, so its mean kinetic energy is kT: the app reads kT = ΣKE / N, in joules. The curve on the histogram is N f(v) Δv, the count a bin of width Δv should hold. With unequal masses it is the average of every body's own curve at the same kT (heavy bodies are slower, with the same mean energy)."),
        New HelpTopic("Pressure and the ideal gas law in 2D",
            "In two dimensions pressure is force per metre of wall (N/m) and volume is area (m²). The app measures it like a gauge: every bounce gives the wall an impulse |Δp| = m |v after − v before|, and" & vbLf & "" & vbLf &
            "  P = Σ|Δp| / (perimeter × time)" & vbLf & "" & vbLf &
            "From the speeds: a body with velocity component vₓ hits the right wall of a box L wide every 2L/vₓ, with impulse 2mvₓ: an average force mvₓ²/L. N bodies on a wall H long give P = N m⟨vₓ²⟩ / (L H), and ⟨vₓ²⟩ = kT/m, so" & vbLf & "" & vbLf &
            "  P A = N k T" & vbLf & "" & vbLf &
            "with A the area the gas has (the box less the fixed bodies). Real balls take up room: at packing fraction η (the balls' area over A) hard discs press harder, by about Z = (1 + η²/8)/(1 − η)² (Henderson). The lesson's gas has η ≈ 0.1 and presses about 23 % harder than N·k·T/A; a gas of small balls follows the ideal law.")}
End Class
