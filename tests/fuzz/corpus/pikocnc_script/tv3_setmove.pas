SetG(1); SetMove(100.0, 90.0); Write;
