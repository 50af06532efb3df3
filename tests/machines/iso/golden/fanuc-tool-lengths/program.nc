%
O1001 (TOOL LENGTHS)
G17 G21 G90
T1 M6
(before G43 the tip is the tool's length below the programmed Z)
G0 X0 Y0
Z150.
G43 H1 Z50.
G1 Z-2. F200
G91 G1 Z1.
G90 G0 Z50.
T2 M6
(the wrong offset: H3 for tool 2 puts the tip 39.5 mm too high)
G43 H3 Z50.
G0 Z10.
G49
G0 Z200.
G43 Z50.
(G92 names the position; the tip stays where it is)
G92 Z0.
G0 Z10.
G43 H0 Z10.
T4 M6
G43 H9 Z10.
M30
%
