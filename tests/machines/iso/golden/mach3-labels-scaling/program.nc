%
O0001 (Mach3: subprograms labelled with ':', G51 scale factors per axis, G50)
G21 G90 G17
G51 X1Y1
G0 X10. Y10. Z5.
M98 P7
G51 X2. Y2.
G0 X10. Y10.
G2 X15. Y10. R2.5 F100
G50
G0 X0 Y0
G76 X5. Y5. Z-3. R1. F50
G74 X6. Z-3. R1. F50
G80
M30
:7
G1 X12. F200
M99
%
