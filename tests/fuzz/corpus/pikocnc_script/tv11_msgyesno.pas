if MsgYesNo('Second pass?') then begin SetG(1); SetZ(-2); Write; end;
