// Spec TV-1: the document's own Write example.
SetM(3); Write;
SetG(0); SetX(10.0); SetY(20.0); Write;
SetZ(1); Write;
SetG(1); SetZ(-1.0); SetF(1000); Write;
