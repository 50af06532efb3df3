// Spec section 10: arguments, answers, constants and the parameters file without a user (TV-10,
// TV-11), and a script's G-code read back through the PikoCNC reader.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "machines/pikocnc/model/reader.hpp"
#include "machines/pikocnc/script/script.hpp"

namespace {

using pikocnc::script::RunInputs;

// The document's argument example (6.4) with its variables declared; prints what it read.
const char* kFront = R"J(var szer, wys, luk_wys, odstep: Extended; Fxy: Integer; rogi: Boolean;
if (RUN_CNT=0) then begin
  SetArgPic('meblowy_info.jpg');
  SetArg(0,'Szerokość frontu (mm)',120.0);
  SetArg(1,'Wysokość frontu (mm)',60.0);
  SetArg(2,'Wysokość łuku (mm)',20.0);
  SetArg(3,'Odległość od krawędzi (mm)',10.0);
  SetArg(4,'*Górna linia/Łuk/Prosta',0);
  SetArg(5,'Szybkość obróbki w osi XY (mm/min)',2000);
  SetArg(6,'Zaokrąglone rogi',FALSE);
end;
ArgPageTitle('Wymiary frontu');
ArgShow(0);
ArgShow(1);
ArgShow(2);
ArgSeparator("");
ArgSeparator('Autor: Andrzej Woźniak    Damasławek 2016');
ArgNewPage('Łuk 3');
ArgShow(3);
ArgShow(4);
ArgShow(5);
ArgNewPage('Łuk 2');
ArgShow(6);
ArgEdit;
szer:=Arg(0); wys:=Arg(1); luk_wys:=Arg(2); odstep:=Arg(3);
Fxy:=Arg(5); rogi:=Arg(6);
SetComment(FloatToStr(szer) + ' ' + FloatToStr(wys) + ' ' + FloatToStr(luk_wys) + ' ' + FloatToStr(odstep) + ' ' +
  IntToStr(Arg(4)) + ' ' + IntToStr(Fxy)); Write;
if rogi then SetComment('rogi'); Write;
)J";

struct Result {
  std::string out, diag, error;
};

Result run(const std::string& text, const RunInputs& inputs) {
  Result r;
  std::ostringstream out, diag;
  try {
    pikocnc::script::run_script_text(text, "front.pas", inputs, out, diag);
  } catch (const toolpath::InputError& e) {
    r.error = e.what();
  }
  r.out = out.str();
  r.diag = diag.str();
  return r;
}

TEST(ScriptArgs, Tv10Defaults) {
  const auto r = run(kFront, {});
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.out, "%\n(120 60 20 10 0 2000)\n");
}

TEST(ScriptArgs, Tv10Overrides) {
  RunInputs in;
  in.args = {{"0", "150"}, {"4", "Prosta"}, {"6", "yes"}};
  const auto r = run(kFront, in);
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.out, "%\n(150 60 20 10 1 2000)\n(rogi)\n");
}

TEST(ScriptArgs, Tv10BadOverrides) {
  RunInputs in;
  in.args = {{"5", "1800.5"}};
  EXPECT_NE(run(kFront, in).error.find("argument 5 (`Szybkość obróbki w osi XY (mm/min)`) is an integer field"), std::string::npos);
  in.args = {{"9", "1"}};
  EXPECT_NE(run(kFront, in).error.find("argument 9 is not defined by the script"), std::string::npos);
  in.args = {{"4", "7"}};
  EXPECT_NE(run(kFront, in).error.find("is a combo field: `7` is not an item's index (0..1)"), std::string::npos);
  in.args = {{"0", "1,5"}};
  EXPECT_EQ(run(kFront, in).out, "%\n(1.5 60 20 10 0 2000)\n");
}

TEST(ScriptArgs, Tv10DescribeArgs) {
  RunInputs in;
  in.describe_args = true;
  const auto r = run(kFront, in);
  EXPECT_EQ(r.error, "");
  EXPECT_EQ(r.out, R"J({
  "picture": "meblowy_info.jpg",
  "tabs": [
    {"title": "Wymiary frontu", "items": [
      {"arg": 0, "label": "Szerokość frontu (mm)", "kind": "float", "value": 120.0},
      {"arg": 1, "label": "Wysokość frontu (mm)", "kind": "float", "value": 60.0},
      {"arg": 2, "label": "Wysokość łuku (mm)", "kind": "float", "value": 20.0},
      {"separator": ""},
      {"separator": "Autor: Andrzej Woźniak    Damasławek 2016"}
    ]},
    {"title": "Łuk 3", "items": [
      {"arg": 3, "label": "Odległość od krawędzi (mm)", "kind": "float", "value": 10.0},
      {"arg": 4, "label": "Górna linia", "kind": "combo", "items": ["Łuk", "Prosta"], "value": 0},
      {"arg": 5, "label": "Szybkość obróbki w osi XY (mm/min)", "kind": "integer", "value": 2000}
    ]},
    {"title": "Łuk 2", "items": [
      {"arg": 6, "label": "Zaokrąglone rogi", "kind": "boolean", "value": false}
    ]}
  ]
}
)J");
}

TEST(ScriptArgs, NoLayoutShowsEveryArgumentByNumber) {
  RunInputs in;
  in.describe_args = true;
  const auto r = run("SetArg(2,'b','x'); SetArg(0,'a',TRUE); ArgEdit; SetX(1); Write;", in);
  EXPECT_EQ(r.out, R"J({
  "picture": null,
  "tabs": [
    {"title": "", "items": [
      {"arg": 0, "label": "a", "kind": "boolean", "value": true},
      {"arg": 2, "label": "b", "kind": "string", "value": "x"}
    ]}
  ]
}
)J");
}

TEST(ScriptArgs, OverridesWithoutArgEditWarn) {
  RunInputs in;
  in.args = {{"0", "1"}};
  const auto r = run("SetArg(0,'a',1); SetX(Arg(0)); Write;", in);
  EXPECT_EQ(r.out, "%\nX1.0\n");
  EXPECT_NE(r.diag.find("never calls ArgEdit"), std::string::npos) << r.diag;
}

const char* kTv11 = "if MsgYesNo('Second pass?') then begin SetG(1); SetZ(-2); Write; end;";

TEST(ScriptAnswers, Tv11) {
  RunInputs in;
  in.ordered_answers = {false};
  EXPECT_EQ(run(kTv11, in).out, "%\n");
  in.ordered_answers = {true};
  EXPECT_EQ(run(kTv11, in).out, "%\nG1 Z-2.0\n");
  const auto none = run(kTv11, {});
  EXPECT_EQ(none.error.substr(0, 14), "front.pas:1:4:");
  EXPECT_NE(none.error.find("MsgYesNo('Second pass?') needs an answer"), std::string::npos) << none.error;
  in = {};
  in.default_answer = true;
  EXPECT_EQ(run(kTv11, in).out, "%\nG1 Z-2.0\n");
}

TEST(ScriptMessages, GoToDiagnosticsNeverToGcode) {
  const auto r = run("MsgOk('hello'); Log('to log'); Dbg('debug'); Dbg_clr; SetX(MAT_SIZE_Y); Write;", {});
  EXPECT_EQ(r.out, "%\nX0.0\n");
  EXPECT_NE(r.diag.find("MsgOk: hello\nLog: to log\nDbg: debug\n"), std::string::npos) << r.diag;
  EXPECT_NE(r.diag.find("default 0 (give them with --const or [constants]): MAT_SIZE_Y"), std::string::npos) << r.diag;
}

TEST(ScriptParameters, FileSectionsAndCommandLinePrecedence) {
  RunInputs in;
  in.constants["MAT_SIZE_X"] = "700";  // the command line wins over the file
  pikocnc::script::read_parameters(R"J([constants]
MAT_SIZE_X = 600
MAT_SIZE_Y = 400   # comment
; comment line
[args]
0 = 150.0
[answers]
"Mill the second side?" = yes
* = no
)J", "p.ini", in);
  EXPECT_EQ(in.constants["MAT_SIZE_X"], "700");
  EXPECT_EQ(in.constants["MAT_SIZE_Y"], "400");
  EXPECT_EQ(in.args["0"], "150.0");
  EXPECT_TRUE(in.answers["Mill the second side?"]);
  EXPECT_EQ(in.default_answer, false);
  const auto r = run("SetX(MAT_SIZE_X); SetY(MAT_SIZE_Y); Write; if MsgYesNo('other') then Write;", in);
  EXPECT_EQ(r.out, "%\nX700.0 Y400.0\n");
  RunInputs bad;
  try {
    pikocnc::script::read_parameters("[args]\n0 150\n", "p.ini", bad);
    FAIL();
  } catch (const toolpath::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "p.ini:2:1: expected `key = value`");
  }
  RunInputs unknown;
  unknown.constants["NOPE"] = "1";
  EXPECT_NE(run("Write;", unknown).error.find("unknown constant `NOPE`"), std::string::npos);
}

// The generated program is PikoCNC G-code: the controller model reads it back into motion.
TEST(ScriptReadBack, PikoReaderReadsTheOutput) {
  const auto r = run(R"J(var i: Integer;
SetG(0); SetX(0); SetY(0); Write; SetZ(2); Write;
SetG(1); SetZ(-1); SetF(300); Write;
SetAngle(0);
for i := 1 to 4 do begin SetMoveR(50, 90 * Ord(i > 1)); Write; end;
SetG(3); SetX(GetX + 20); SetBulge(5); Write;
SetG(0); SetZ(5); Write; SetM(30); Write;
)J", {});
  ASSERT_EQ(r.error, "");
  std::istringstream nc(r.out);
  pikocnc::PikoReader reader(nc, "out.nc");
  toolpath::Command c;
  int lines = 0, arcs = 0;
  while (reader.next(c)) {
    lines += c.name == "@line";
    arcs += c.name == "@arc";
  }
  EXPECT_GE(lines, 5);
  EXPECT_EQ(arcs, 1);
}

}  // namespace
