(a WHILE whose END1 never comes: the file ends inside the loop)
#1 = 0
WHILE [#1 LT 1] DO1
G0 X1.
