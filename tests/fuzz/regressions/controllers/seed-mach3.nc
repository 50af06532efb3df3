À%
O0001 (Mach3: G4 P in seconds, M98 P L, no o-words)
G21 G90 G17 G54
M3 S12000
G0 X0 Y0 Z5.
G4 P1.5
M98 P10 L2
o101 repeat [2]
o101 endrepeat
G0 Z50.
M5
M30
O10
G91 G1 Z-1. F100
G90
M99
%
