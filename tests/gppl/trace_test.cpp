// Trace output in SolidCAM's layout (spec 8, solidcam-behaviour.md 1): header with the nesting
// level padded to column 21, parameters the host assigned, emitted lines after `>`.
#include <gtest/gtest.h>

#include <sstream>

#include "support.hpp"

using namespace gppl_test;

namespace {

const char* kPost = R"(@init_post
trace "all":5
{nb, 'never traced'}
endp
@line
{nb, 'G1 X'xpos}
call @usr_spindle_output
endp
@usr_spindle_output
{nb, 'S1910'}
call @inner
endp
@inner
endp
)";

TEST(Trace, LevelFiveLayout) {
  Post post(kPost);
  std::ostringstream trace;
  post.run->set_trace_stream(&trace);
  post.run->start();
  post.set("xpos", numeric(70.));
  post.set("ypos", numeric(-45.4760057628), gppl::ChangeOverride::ForceUnchanged);
  post.set("g_file_name", string("PART.MPF"));
  post.set("home_number", integer(54));
  post.call("@line");
  post.run->trace_unhandled("@tmatrix");
  post.run->finish();
  EXPECT_EQ(trace.str(),
            "(1)@line            ==> xpos:70.000T ypos:-45.4760057628F g_file_name:'PART.MPF' home_number:54\n"
            "                      > never traced\n"
            "(2)@usr_spindle_outp==>\n"
            "   ut                 > G1 X70\n"
            "(3)@inner           ==>\n"
            "(0)@tmatrix         ==>\n"
            "                      > S1910\n");
}

TEST(Trace, SelectedProceduresAndLevels) {
  Post post(R"(@init_post
trace "all":0
trace " @line , @arc ":1
trace "@rapid_move":2
endp
@line
{nb, 'L'}
endp
@arc
{nb, 'A'}
endp
@rapid_move
{nb, 'R'}
endp
@other
{nb, 'O'}
endp
)");
  std::ostringstream trace;
  post.run->set_trace_stream(&trace);
  post.run->start();
  for (const char* p : {"@line", "@arc", "@rapid_move", "@other", "@line"}) post.call(p);
  post.run->trace_unhandled("@tmatrix");
  post.run->finish();
  EXPECT_EQ(trace.str(),
            "(1)@line            ==>\n(1)@arc             ==>\n(1)@rapid_move      ==>\n"
            "                      > A\n                      > R\n(1)@line            ==>\n");
  EXPECT_EQ(post.text(), "L\nA\nR\nO\nL");
}

TEST(Trace, ContinuationLines) {
  Post post("@init_post\ntrace 'all':3\nendp\n@job\nendp\n");
  std::ostringstream trace;
  post.run->set_trace_stream(&trace);
  post.run->start();
  for (int i = 0; i < 8; ++i) post.set("parameter_" + std::to_string(i), integer(1000 + i));
  post.call("@job");
  EXPECT_EQ(trace.str(),
            "(1)@job             ==> parameter_0:1000 parameter_1:1001 parameter_2:1002 parameter_3:1003\n"
            "                    ..> parameter_4:1004 parameter_5:1005 parameter_6:1006 parameter_7:1007\n");
}

TEST(Trace, VariableLevel) {
  Post post("@init_post\nGPX_TRACE = 1\ntrace \"all\":GPX_TRACE\nendp\n@t\nendp\n");
  std::ostringstream trace;
  post.run->set_trace_stream(&trace);
  post.run->start();
  post.call("@t");
  EXPECT_EQ(trace.str(), "(1)@t               ==>\n");
}

// The list text is found by its constant index, whatever nodes the expressions before it made.
TEST(Trace, ListAfterOtherExpressions) {
  Post post("@init_post\nx = a + b * c\ny = x - a\ntrace \"@t\":1\nendp\n@t\nendp\n@u\nendp\n");
  std::ostringstream trace;
  post.run->set_trace_stream(&trace);
  post.run->start();
  post.call("@u");
  post.call("@t");
  EXPECT_EQ(trace.str(), "(1)@t               ==>\n");
}

}  // namespace
