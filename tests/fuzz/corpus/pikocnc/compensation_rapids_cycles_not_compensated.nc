%
G41 R1
G0 X10 Y10      (no chain follows: the programmed point)
G0 X20 Y10
G0 Z2 G98
G81 X30 Y10 Z-5 R1 F100  (cycles are not compensated)
X40
G80
G0 X50 Y0       (approach)
G1 Z-1
G1 X60
G53 G0 Z0       (a machine move ends the contour)
G40
