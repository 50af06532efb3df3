(macro B expressions and functions; R arcs of either length)
G21 G90 G17
#1 = SIN[30] + SQRT[16] + ATAN[1]/[1] + FIX[-1.5] + FUP[1.2]
G0 X#1
#2 = [#1 GT 50] AND [#1 LT 51]
G0 Y#2
G0 X0 Y0
G2 X10. Y0 R6. F100
G0 X0 Y0
G2 X10. Y0 R-6.
G1 X[ABS[-3]] Y[ROUND[2.5]]
G95 G1 X4. F0.1
#3 = SQRT[-1]
M30
