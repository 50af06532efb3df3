SetG(0); SetX(0); SetY(0); Write;
SetG(1); SetF(500); SetAngle(0);
SetMoveR(10, 0); Write;
SetMoveR(10, 90); Write;
SetMoveR(10, 90); Write;
SetMoveR(10, 90); Write;
