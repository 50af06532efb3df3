// Spec TV-2: the document's TPoint/TLine example (section 5), declarations added.
var ln: TLine; pt: TPoint;
ln.s.x := 0.0;  ln.s.y := 1.0;       // start
ln.e.x := 10.0; ln.e.y := 15.0;      // end
pt := ln.s;                          // a copy of the start
SetG(0); SetX(ln.s.x); SetY(ln.s.y); Write;
SetG(1); SetX(ln.e.x); SetY(ln.e.y); Write;
SetG(0); SetPT(ln.s); Write;
SetG(1); SetPT(ln.e); Write;
ln.s.x := 99;                        // pt is a copy: unchanged
SetComment('pt=' + FloatToStr(pt.x) + ',' + FloatToStr(pt.y)); Write;
