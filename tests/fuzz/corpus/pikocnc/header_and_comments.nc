Short program        ; ignored
2 mm cutter          ; ignored
G0 X30 Y30           ; ignored, although it is valid G-code
%                    ; program starts here
G0 X10 Y10
G0 Z-1
G1 X20 Y20 F100
G0 X1 (approach) Y2
%
