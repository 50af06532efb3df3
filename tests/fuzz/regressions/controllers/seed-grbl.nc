À%
(GRBL: no cycles, tool changer or subprograms; G4 P in seconds)
G21 G90 G17
G0 X10. Y10.
G81 X1. Z-1. R1.
T2 M6
M98 P1
G2 X20. Y10. R-5. F100
G53 G0 Z-1.
G4 P0.25
M30
