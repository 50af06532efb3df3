var a: Extended;
SetG(0); SetX(5); SetY(7); Write;
SetZ(2); Write;
a := GetX + GetY + GetZ;
SetG(1); SetX(a); SetF(250.5); Write;
SetM(30); SetComment('end'); Write;
