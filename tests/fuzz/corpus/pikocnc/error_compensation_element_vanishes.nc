%
G41 R3
G0 X0 Y0
G1 Z-1 F100
G1 X20
G1 Y1   (shorter than the radius: disappears)
G1 X40
G0 Z5
G40
