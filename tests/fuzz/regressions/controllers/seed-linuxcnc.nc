À(LinuxCNC: o-word subs with arguments, repeats, G4 P in seconds, G18 arcs, inch)
G21 G90 G17
#1 = 2
o100 sub
  G1 X#1 Y#2 F300
o100 endsub
o101 repeat [3]
  G91 G1 Z-1. F50
  G90
o101 endrepeat
o100 call [5] [6]
G0 X#1
G4 P0.5
G18 G2 X10. Z-3. I4. K0 F100
G17 G91 G3 X-10. Y0 R5.
G90 G20 G0 X1.
G53 G0 Z0
M2
