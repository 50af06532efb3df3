SetG(0); SetX(0); SetY(0); Write;
SetG(3); SetX(100); SetBulge(20); Write;
SetG(0); SetX(0); Write;
SetG(3); SetX(100); SetBulge(80); Write;
