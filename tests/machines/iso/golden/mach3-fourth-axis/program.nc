(Mach3 4-axis: A angles absolute and incremental; every move carries apos once A is used)
(G53 A0, as SolidCAM's Mach3 post homes the axis, turns A in machine coordinates)
O1
G21 G90 G17
G0 X0 Y0 Z5. A0
G1 X10. A90. F100
G0 A180.
G91 G0 A-45.
G90
G0 G53 Z0
G0 G53 X0 Y0 A0
G1 X5. F100
M30
%
