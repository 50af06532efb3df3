// A furniture front with an arched (or straight) top, cut out along its outline: the document's
// argument example (section 6.4) made into a complete script. Run it with
//   postproc script run machines/pikocnc/scripts/front.pas --arg 0=150 --arg 4=Prosta -o front.nc
var
  szer, wys, luk_wys, odstep, glebokosc, krok, z: Extended;
  Fxy, przejscia, i: Integer;
  rogi, prosta: Boolean;

// One pass around the outline at depth z, counter-clockwise from the bottom-left corner.
procedure Outline(z: Extended);
var r: Extended;
begin
  if rogi then r := odstep else r := 0;
  SetG(1); SetZ(z); SetF(Fxy / 2); Write;
  SetX(szer - r); SetF(Fxy); Write;
  if rogi then begin SetG(3); SetX(szer); SetY(r); SetR(r); Write; SetG(1); end;
  SetY(wys - luk_wys); Write;
  if prosta then begin
    SetX(0); SetY(wys - luk_wys); Write;       // straight top (at the arc's start height)
  end else begin
    SetG(3); SetX(0); SetBulge(luk_wys); Write; // the arch: its height is luk_wys
    SetG(1);
  end;
  SetY(r); Write;
  if rogi then begin SetG(3); SetX(r); SetY(0); SetR(r); Write; SetG(1); end;
end;

begin
  if (RUN_CNT = 0) then begin
    SetArgPic('meblowy_info.jpg');
    SetArg(0, 'Szerokość frontu (mm)', 120.0);
    SetArg(1, 'Wysokość frontu (mm)', 60.0);
    SetArg(2, 'Wysokość łuku (mm)', 20.0);
    SetArg(3, 'Promień rogów (mm)', 10.0);
    SetArg(4, '*Górna linia/Łuk/Prosta', 0);
    SetArg(5, 'Szybkość obróbki w osi XY (mm/min)', 2000);
    SetArg(6, 'Zaokrąglone rogi', FALSE);
    SetArg(7, 'Głębokość (mm)', 18.0);
    SetArg(8, 'Głębokość przejścia (mm)', 6.0);
  end;
  ArgPageTitle('Wymiary frontu');
  ArgShow(0); ArgShow(1); ArgShow(2);
  ArgSeparator('');
  ArgNewPage('Obróbka');
  ArgShow(3); ArgShow(4); ArgShow(5); ArgShow(6); ArgShow(7); ArgShow(8);
  ArgEdit;

  szer := Arg(0); wys := Arg(1); luk_wys := Arg(2); odstep := Arg(3);
  prosta := Arg(4) = 1; Fxy := Arg(5); rogi := Arg(6);
  glebokosc := Arg(7); krok := Arg(8);
  if (luk_wys <= 0) or (luk_wys >= wys) then begin
    MsgOk('The arc height must be between 0 and the front height: using a straight top');
    prosta := TRUE;
  end;
  if krok <= 0 then krok := glebokosc;
  przejscia := Trunc(glebokosc / krok);
  if przejscia * krok < glebokosc - 0.0001 then przejscia := przejscia + 1;

  SetComment('front ' + FloatToStr(szer) + ' x ' + FloatToStr(wys)); Write;
  SetG(90); Write;
  SetG(0); SetZ(5); Write;
  if rogi then SetX(odstep) else SetX(0);
  SetY(0); Write;
  for i := 1 to przejscia do begin
    z := -i * krok;
    if z < -glebokosc then z := -glebokosc;
    Outline(z);
  end;
  SetG(0); SetZ(5); Write;
  SetM(30); Write;
end.
