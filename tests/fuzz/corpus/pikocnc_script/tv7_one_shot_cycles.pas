SetG(1); SetX(1); SetF(100); Write;
SetG(4); SetP(0.5); Write;
SetX(2); Write;
SetG(0); SetZ(2); Write;
SetG(81); SetX(40); SetY(100); SetZ(-3.2); SetR(1); SetF(150); Write;
SetX(50); SetY(100); Write;
SetG(80); Write;
SetT(5); SetM(6); Write;
SetS(12000); SetM(3); Write;
