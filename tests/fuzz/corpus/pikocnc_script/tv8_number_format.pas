SetG(1); SetX(10.123456); Write;
SetG(1); SetX(-0.00001); Write;
SetG(1); SetY(2.5); SetF(1250.5); Write;
SetG(2); SetX(10); SetI(-5); SetJ(0); Write;
SetG(4); SetP(2); Write;
