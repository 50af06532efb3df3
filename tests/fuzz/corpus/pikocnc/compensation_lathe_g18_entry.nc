%
(lathe profile: G42 in G18 needs a G1 entry move, 2025 document)
G18
G0 X20 Z5
G42 R1
G1 X10 Z2 F0.2   (entry move)
G1 Z-20
X16
X20 Z-23
G0 X30
G40
G0 Z5
