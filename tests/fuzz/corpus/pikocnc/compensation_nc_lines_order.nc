%
G42 R2
G0 X0 Y0
G1 Z-1 F100 M8
G1 X20 (first side)
M9 (coolant off between two elements)
G1 Y20
G1 X0 M0
G0 Z5
G40
