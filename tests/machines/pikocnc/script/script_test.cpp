// PikoCNC scripts: the spec's worked examples as golden folders (script.pas -> expected.nc, with an
// optional params.ini), the built-ins and the errors as tables.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "machines/pikocnc/script/script.hpp"

namespace {

namespace fs = std::filesystem;
using pikocnc::script::RunInputs;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Ran {
  std::string out, diag, error;
};

Ran run(const std::string& text, RunInputs inputs = {}) {
  Ran r;
  std::ostringstream out, diag;
  try {
    pikocnc::script::run_script_text(text, "t.pas", inputs, out, diag);
  } catch (const toolpath::InputError& e) {
    r.error = e.what();
  }
  r.out = out.str();
  r.diag = diag.str();
  return r;
}

// The G-code after the leading `%` line.
std::string body(const std::string& text, RunInputs inputs = {}) {
  const Ran r = run(text, std::move(inputs));
  EXPECT_EQ(r.error, "") << text;
  return r.out.rfind("%\n", 0) == 0 ? r.out.substr(2) : r.out;
}

TEST(ScriptGolden, SpecWorkedExamples) {
  int count = 0;
  for (const auto& dir : fs::directory_iterator("machines/pikocnc/script/golden")) {
    SCOPED_TRACE(dir.path().string());
    RunInputs inputs;
    if (fs::exists(dir.path() / "params.ini"))
      pikocnc::script::read_parameters(slurp(dir.path() / "params.ini"), "params.ini", inputs);
    std::ostringstream out, diag;
    pikocnc::script::run_script_text(slurp(dir.path() / "script.pas"), "script.pas", inputs, out, diag);
    EXPECT_EQ(out.str(), slurp(dir.path() / "expected.nc"));
    ++count;
  }
  EXPECT_GE(count, 9);
}

struct Case {
  const char* script;
  const char* expected;  // output after `%`
};

// TV-9 and the other built-ins, printed through comments.
const Case kBuiltins[] = {
    {"var l, r: TLine; begin l.e.x := 10; r := LinePar(l, 2); SetComment(FloatToStr(r.s.x) + ' ' + FloatToStr(r.s.y) + ' ' + "
     "FloatToStr(r.e.x) + ' ' + FloatToStr(r.e.y)); Write; end.",
     "(0 2 10 2)\n"},
    {"var l, r: TLine; begin l.e.x := 10; r := LinePar(l, -2); SetComment(FloatToStr(r.s.y) + ' ' + FloatToStr(r.e.y)); Write; end.",
     "(-2 -2)\n"},
    {"var a, b: TLine; pc: TPoint; ok: Boolean; begin a.e.x := 10; a.e.y := 10; b.s.y := 10; b.e.x := 10;\n"
     "ok := LineInt(a, b, pc); if ok then SetComment(FloatToStr(pc.x) + ',' + FloatToStr(pc.y)); Write; end.",
     "(5,5)\n"},
    {"var a, b: TLine; pc: TPoint; begin a.e.x := 1; a.e.y := 1; b.s.y := 10; b.e.x := 10; pc.x := 7;\n"
     "if not LineInt(a, b, pc) then SetComment('no ' + FloatToStr(pc.x)); Write; end.",
     "(no 7)\n"},
    {"var a, b: TLine; pc: TPoint; begin a.e.x := 10; b.s.y := 1; b.e.x := 10; b.e.y := 1;\n"
     "if not LineInt(a, b, pc) then SetComment('parallel'); Write; end.",
     "(parallel)\n"},
    {"var a, b: TLine; pc: TPoint; begin a.e.x := 10; b.s.x := 10; b.e.x := 10; b.e.y := 5;\n"
     "if LineInt(a, b, pc) then SetComment(FloatToStr(pc.x) + ',' + FloatToStr(pc.y)); Write; end.",
     "(10,0)\n"},
    {"var l, r: TLine; begin l.e.x := 10; r := LineExp(l, 5); SetComment(FloatToStr(r.s.x) + ' ' + FloatToStr(r.e.x)); Write;\n"
     "r := LineExp(l, -2); SetComment(FloatToStr(r.s.x) + ' ' + FloatToStr(r.e.x)); Write; end.",
     "(-5 15)\n(2 8)\n"},
    {"SetX(CirPointX(10, 60)); SetY(CirPointY(10, 30)); Write;", "X5.0 Y5.0\n"},
    {"SetComment(FloatToStr(1/3)); Write;", "(0.333333333333333)\n"},
    {"SetComment(FloatToStr(2.5) + ' ' + FloatToStr(10) + ' ' + FloatToStr(0.1+0.2) + ' ' + FloatToStr(-0.25)); Write;",
     "(2.5 10 0.3 -0.25)\n"},
    {"SetComment(FloatToStr(0.00001) + ' ' + FloatToStr(1.5e20)); Write;", "(1E-5 1.5E20)\n"},
    {"SetComment(IntToStr(Round(2.5)) + IntToStr(Round(3.5)) + IntToStr(Round(-2.5)) + IntToStr(Trunc(-2.7))); Write;",
     "(24-2-2)\n"},
    {"SetX(Sqrt(16) + Sqr(2) + Abs(-1.5) + Int(2.7) + Frac(0.25)); Write;", "X11.75\n"},
    {"SetX(Sin(Pi/2) + Cos(0) + Tan(0) + ArcSin(1)*2/Pi + ArcCos(1) + ArcTan(1)*4/Pi); Write;", "X4.0\n"},
    {"SetX(Ln(Exp(2)) + Power(2, 10)); Write;", "X1026.0\n"},
    {"SetComment(IntToStr(Length('abc')) + Copy('abcdef', 2, 3) + IntToStr(Pos('cd', 'abcdef')) + UpperCase('x') + "
     "LowerCase('Y') + Trim('  z  ') + IntToStr(StrToInt('12') + 1) + FloatToStr(StrToFloat('1.5'))); Write;",
     "(3bcd3Xyz131.5)\n"},
    {"SetComment('it''s' + #65 + \"dq\"); Write;", "(it'sAdq)\n"},
    {"SetComment('Szerokość frontu'); Write;", "(Szerokość frontu)\n"},
    {"SetComment('two' + #10 + 'lines'); Write;", "(two lines)\n"},
    {"var i, s: Integer; begin s := 0; for i := 1 to 10 do s := s + i; for i := 3 downto 1 do s := s * 2; SetX(s); Write; end.",
     "X440.0\n"},
    {"var i: Integer; begin i := 0; while i < 5 do begin i := i + 1; if i = 3 then break; end; SetX(i); Write;\n"
     "repeat i := i + 10 until i > 40; SetY(i); Write; end.",
     "X3.0\nY43.0\n"},
    {"var i, n: Integer; begin n := 0; for i := 1 to 10 do begin if i mod 2 = 0 then continue; n := n + 1; end; SetX(n); Write; end.",
     "X5.0\n"},
    {"function Sq(x: Extended): Extended; begin Result := x * x; end;\n"
     "function Fact(n: Integer): Integer; begin if n <= 1 then Fact := 1 else Fact := n * Fact(n - 1); end;\n"
     "procedure Twice(var v: Integer); begin v := v * 2; end;\n"
     "var k: Integer; begin k := 4; Twice(k); SetX(Sq(3) + Fact(5) + k); Write; end.",
     "X137.0\n"},
    {"function F: Integer; begin Result := 3; end; SetX(F + F()); Write;", "X6.0\n"},
    {"procedure P(n: Integer); begin if n > 2 then exit; SetX(n); Write; end; begin P(1); P(5); end.", "X1.0\n"},
    {"const N = 3; W = N * 2.5; var a: array[0..N] of Integer; i: Integer;\n"
     "begin for i := 0 to N do a[i] := i * i; SetX(a[3] + W); Write; end.",
     "X16.5\n"},
    {"var s: String; i: Integer; begin i := 2; case i of 1: s := 'one'; 2, 3: s := 'two'; else s := 'many'; end;\n"
     "SetComment(s); Write; end.",
     "(two)\n"},
    {"var v: Variant; x: Extended; n: Integer; begin v := 2.5; x := v; v := 7; n := v; SetX(x + n); Write; end.", "X9.5\n"},
    {"var b: Boolean; begin b := (1 < 2) and not (3 = 4) or false; if b then SetX(1); Write; end.", "X1.0\n"},
    {"var i: Integer; begin i := $FF xor 15; Inc(i); Dec(i, 2); SetX(i); SetY(7 div 2 + 7 mod 2); Write; end.", "X239.0 Y4.0\n"},
    {"{ brace } (* paren *) SetX(1); // line\nWrite;", "X1.0\n"},
    {"program Demo; var x: Extended; begin x := 1.5e3; SetF(x); SetS(12000.5); Write; end.", "F1500 S12000.5\n"},
    {"SetX(1); Write; SetX(MAT_SIZE_X + RUN_CNT); Write;", "X1.0\nX0.0\n"},
    {"Write; SetComment(''); Write;", "()\n"},
    {"SetG(83); SetX(1); SetA(90); SetQ(2); SetR(-1); Write; SetG(0); SetZ(3); Write; SetX(GetZ); Write;",
     "G83 X1.0 A90.0 R-1.0 Q2.0\nG0 Z3.0\nG0 X3.0\n"},
    {"SetAngle(90); SetMoveR(10, -90); Write; SetMoveR(5, 90); Write; SetMove(2, 180); Write;", "X10.0 Y0.0\nX10.0 Y5.0\nX8.0 Y5.0\n"},
    {"SetComment(IntToStr(Min(3, 2)) + FloatToStr(Max(1.5, 2)) + Chr(66) + IntToStr(Ord('A')) + IntToStr(Ord(Odd(3)))); Dbg_clr; Write;",
     "(22B651)\n"},
    {"var ln: TLine; begin ln.e.x := Exp(0); SetX(ln.e.x); Write; end.", "X1.0\n"},
};

TEST(ScriptBuiltins, Table) {
  for (const auto& c : kBuiltins) {
    SCOPED_TRACE(c.script);
    EXPECT_EQ(body(c.script), c.expected);
  }
}

// Every error names t.pas:line:column and what went wrong.
const Case kErrors[] = {
    {"SetX(1", "t.pas:1:7: expected ')'"},
    {"SetX(1);\nSetY(2) Write;", "t.pas:2:9: expected ';' or the end of the script"},
    {"begin SetX(1); end. SetX(2);", "t.pas:1:19: expected ';' or the end of the script"},
    {"begin SetX(1) SetY(1) end.", "t.pas:1:15: expected ';' or 'end'"},
    {"SetComment('abc);", "t.pas:1:18: expected a closing ' (unterminated string)"},
    {"{ open comment", "t.pas:1:15: expected '}' closing the comment"},
    {"if 1 < 2 SetX(1);", "t.pas:1:10: expected 'then'"},
    {"SetX(1);\nvar a: Integer;", "t.pas:2:1: expected every declaration (var, const, type, procedure, function) before the first statement"},
    {"SetX(Foo());", "t.pas:1:6: unknown identifier `Foo`"},
    {"Foo(1);", "t.pas:1:1: unknown identifier `Foo`"},
    {"Writeln('x');", "t.pas:1:1: unknown identifier `Writeln`"},
    {"var x: Integer;\nx := 1.5;", "t.pas:2:6: type mismatch: assignment to `x` expects Integer, got Extended"},
    {"var s: String;\ns := 1 + 'a';", "t.pas:2:8: operator `+` cannot be applied to Integer and String"},
    {"SetX(1, 2);", "t.pas:1:1: `SetX` takes 1 argument(s), 2 given"},
    {"Write('x');", "t.pas:1:1: `Write` takes 0 argument(s), 1 given (Write writes"},
    {"SetComment(5);", "t.pas:1:12: type mismatch: argument 1 of `SetComment` expects String, got Integer"},
    {"var x: Integer;\nx := 0;\nSetX(1 / x);", "t.pas:3:8: division by zero"},
    {"var x: Integer;\nx := 0;\nSetX(1 div x);", "t.pas:3:8: division by zero"},
    {"SetX(1 / 0);", "t.pas:1:8: division by zero"},
    {"while true do ;", "runaway script: more than 100000 statements executed"},
    {"procedure P; begin P; end; begin P; end.", "t.pas:1:20: runaway recursion"},
    {"SetG(300);", "t.pas:1:6: 300 is out of the Byte range 0..255"},
    {"SetX(ArcSin(2));", "t.pas:1:6: ArcSin: argument 2 is outside the domain"},
    {"SetX(Sqrt(-1));", "t.pas:1:6: Sqrt: argument -1 is outside the domain"},
    {"SetG(2); SetBulge(5);", "SetBulge needs the arc's end point"},
    {"SetBulge(5);", "t.pas:1:1: SetBulge needs SetG(2) or SetG(3) first"},
    {"SetX(Arg(3));", "t.pas:1:6: argument 3 is not defined"},
    {"MAT_SIZE_X := 5;", "t.pas:1:1: cannot assign to `MAT_SIZE_X`: it is a constant"},
    {"break;", "t.pas:1:1: `break` outside a loop"},
    {"var p: TPoint;\np.z := 1;", "t.pas:2:3: TPoint has no field `z`"},
    {"var x: Integer;\nx;", "t.pas:2:1: a statement cannot be just a value"},
    {"var x: Foo;", "t.pas:1:8: unknown type `Foo`"},
    {"var i: Integer;\ni := 2147483647;\ni := i + 1;", "t.pas:3:8: integer overflow"},
    {"var a: array[1..3] of Integer;\na[4] := 1;", "t.pas:2:2: index 4 is outside the array's bounds 1..3"},
    {"SetX(((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((("
     "((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((((1",
     "nesting too deep"},
    {"SetX(1)\0;", "t.pas:1:8: unexpected NUL byte"},
    {"var s: String; i: Integer;\nbegin s := 'ab'; for i := 1 to 40 do s := s + s; end.", "t.pas:2:45: string too long"},
    {"var a: array[1..1000000] of TLine;", "t.pas:1:14: array too large"},
    {"procedure P; var a: array[1..20000] of Integer; begin end;", "t.pas:1:18: a local variable may hold at most 10000 values"},
    {"function F(n: Integer): Integer; begin Result := 1 + (1 + (1 + (1 + F(n + 1)))); end;\nbegin SetX(F(0)); end.",
     "runaway recursion"},
    {"SetX(1e300 * 1e300);", "t.pas:1:12: floating-point overflow"},
};

TEST(ScriptErrors, Table) {
  for (const auto& c : kErrors) {
    SCOPED_TRACE(c.script);
    RunInputs inputs;
    inputs.max_steps = 100000;
    const std::string text = std::string(c.script) == "SetX(1)" ? std::string("SetX(1)\0;", 9) : c.script;
    const Ran r = run(text, inputs);
    EXPECT_NE(r.error.find(c.expected), std::string::npos) << r.error;
  }
}

}  // namespace
