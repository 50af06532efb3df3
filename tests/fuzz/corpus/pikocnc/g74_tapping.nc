%
G95 (feed per revolution
G0 Z2. G98 (the current Z is the travel height
M3
G74 X40 Y100 Z-10 R1.0 P0.5 F1.5
X50 Y100
G80 (end of cycle
G74.1 X60 Y110 Z-10 R1.0 F1.5
G80
