%
G0 Z2. G98 (the current Z is the travel height)
G81 X40 Y100 Z-3.2 R1.0 F150
X50 Y100
X60 Y110
X70 Y120
G80
