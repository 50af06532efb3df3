(Mach3 4-axis: A angles absolute and incremental; every move carries apos once A is used)
O1
G21 G90 G17
G0 X0 Y0 Z5. A0
G1 X10. A90. F100
G0 A180.
G91 G0 A-45.
G90
M30
%
