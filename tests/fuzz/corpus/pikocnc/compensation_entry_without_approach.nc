%
G0 X0 Y0 Z-1
G41 R2
G1 X10 Y10 F100   (no G0 approach: entry move)
G1 X30
G1 Y30
G40
G0 Z5
G41 R2
G3 X30 Y50 R10    (starts with an arc: a feed to its offset start is inserted)
G40
