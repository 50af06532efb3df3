%
G0 Z2. G98 ;the current Z is the travel height
G83 X40 Y100 Z-6 Q2.0 R1.0 F150
X50 Y100
G80
