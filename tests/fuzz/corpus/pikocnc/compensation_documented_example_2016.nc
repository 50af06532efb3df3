%
N070 G41 R2.0          ; compensation on
N080 G0 X26 Y46,35     ; approach the start of machining
N090 G0 Z1
N100 G1 Z-3,2 F150     ; plunge and work
N110 G1 X60
N120 Y76,35
N130 X26
N140 Y46,35
N160 G0 Z2             ; lift Z
N150 G40               ; compensation off
N170 G0 X0 Y0
