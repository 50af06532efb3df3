%
G41 R5
G0 X0 Y0
G1 Z-1 F100
G1 X10
G3 X16 Y0 R3  (the tool does not fit inside)
G1 X30
G0 Z5
G40
