%
G20              (inch: R and coordinates in inches)
G42 R0.1
G0 X0 Y-1
G1 Z-0.1 F10
G2 X0 Y-1 I0 J1 Z-0.2  (helical full circle, outside)
G1 X1
G0 Z0.5
G40
