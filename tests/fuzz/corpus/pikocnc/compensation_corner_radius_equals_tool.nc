%
(pocket wall with fillets of the tool radius: the tool pivots in the corners)
G41 R5
G0 X20 Y0
G1 Z-2 F400
G1 X35
G3 X40 Y5 I0 J5
G1 Y25
G3 X35 Y30 I-5 J0
G1 X5
G3 X0 Y25 I0 J-5
G1 Y5
G3 X5 Y0 I5 J0
G1 X20
G0 Z10
G40
