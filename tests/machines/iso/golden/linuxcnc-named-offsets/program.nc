(LinuxCNC: named parameters, G92 and G92.1, G52, a routine from the machine's subroutine folders)
G21 G90 G17
#<depth> = -2.5
#<_step> = [#<depth> / 2]
G0 X10. Y10. Z5.
G92 X0 Y0
G1 X5. Z#<_step> F100
G92.1
G1 X5. Y5.
G52 X100.
G0 X0 Y0
G52 X0
G0 X0 Y0
o100 call
G1 Z#<undefined>
M2
