%
M6 T3            (radius 2 from the tool table)
G68 X0 Y0 R30    (the compensated path is rotated)
G41
G0 X0 Y0
G0 Z1
G25 R2
G91 G1 Z-2 F200
X30
Y20
X-30
Y-20
G90
G125
G0 Z5
G40
G69
G0 X0 Y0
