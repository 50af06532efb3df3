// Leaf procedures copied into their callers (gppl/compile/inline_calls.cpp) against the same posts
// compiled with every call left a call: the same lines, procedures, values, results and errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "gppl/program.hpp"
#include "support.hpp"

namespace {

using gppl_test::Post;

struct Case {
  const char* name;
  const char* source;
  std::vector<const char*> copied;      // procedures whose calls become InlineLeaf
  std::vector<const char*> variables;   // compared after every step
};

// Each post has @init_post and @t, run as a command several times with `step` = 0, 1, 2, ...
const Case kCases[] = {
    {"ForcedGWord",
     R"(@init_post
  global integer gcode
  global logical force_g
  global integer blk
endp
@forced_g
  if blk gt 30
    blk = 10
  endif
  if force_g
    change(gcode) = TRUE
    force_g = FALSE
  endif
endp
@t
  blk = blk + 10
  gcode = 1
  if step eq 2
    force_g = TRUE
  endif
  call @forced_g
  {nb, ['G'gcode], ' B', blk}
endp
)",
     {"@forced_g"},
     {"gcode", "force_g", "blk"}},
    {"ReturnExitAndLoops",
     R"(@init_post
  global integer n
  global integer total
endp
@count
  n = 0
  while n lt step
    n = n + 1
    if n eq 3
      return
    endif
  endw
  total = total + n
endp
@leave
  if step eq 4
    exit
  endif
  total = total + 100
endp
@t
  call @count
  call @count
  call @leave
  {nb, 'N', n, ' T', total}
endp
)",
     {"@count", "@leave"},
     {"n", "total"}},
    {"AbortKeepsTheLine",
     R"(@init_post
  global integer seen
endp
@stop
  if step eq 3
    abort
  endif
  seen = seen + 1
endp
@t
  {nb, 'A', step}
  call @stop
  {' B', seen}
endp
)",
     {"@stop"},
     {"seen"}},
    {"NotCopied",
     R"(@init_post
  global integer a
endp
@with_local
  local integer k
  k = step * 2
  a = a + k
endp
@with_line
  {nb, 'L', a}
endp
@with_call
  call @with_local
endp
@with_arg(integer v)
  a = a + v
endp
@t
  call @with_local
  call @with_line
  call @with_call
  call @with_arg(step)
endp
)",
     {},
     {"a"}},
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

struct Outcome {
  std::vector<std::string> lines, procedures, values, results;
};

std::string show(const gppl::Value& v) {
  switch (v.type) {
    case gppl::Type::Integer: return std::to_string(v.integer);
    case gppl::Type::Numeric: return std::to_string(v.numeric);
    case gppl::Type::Logical: return v.logical ? "TRUE" : "FALSE";
    case gppl::Type::String: return v.text;
  }
  return "?";
}

Outcome run_case(const Case& c, bool copy, std::ostream* trace = nullptr) {
  gppl::CompileOptions options;
  options.inline_leaf_calls = copy;
  Post post(c.source, options);
  if (trace) post.run->set_trace_stream(trace);
  post.run->start();
  Outcome r;
  for (int step = 0; step < 6; ++step) {
    post.set("step", gppl_test::integer(step));
    try {
      r.results.push_back(std::to_string(static_cast<int>(post.call("@t"))));
    } catch (const gppl::Error& e) {
      r.results.push_back(e.what());
    }
    for (const char* v : c.variables) r.values.push_back(show(post.get(v)));
  }
  post.text();
  r.lines = post.out.lines;
  r.procedures = post.out.procedures;
  return r;
}

// The procedures whose calls were copied: the InlineLeaf instructions' targets.
std::vector<std::string> copied_procedures(const gppl::Program& program) {
  std::vector<std::string> names;
  for (const gppl::Instruction& in : program.code)
    if (in.op == gppl::OpCode::InlineLeaf) names.push_back(program.procedures[in.a].name);
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

class InlineCalls : public testing::TestWithParam<Case> {};

TEST_P(InlineCalls, SameRunAsCalls) {
  const Case& c = GetParam();
  const Outcome called = run_case(c, false), copied = run_case(c, true);
  EXPECT_EQ(copied.lines, called.lines);
  EXPECT_EQ(copied.procedures, called.procedures);
  EXPECT_EQ(copied.values, called.values);
  EXPECT_EQ(copied.results, called.results);
  EXPECT_FALSE(called.lines.empty());
}

TEST_P(InlineCalls, CopiesOnlyLeaves) {
  const Case& c = GetParam();
  gppl::CompileOptions options;
  const auto program = gppl::compile_source(c.source, "test.gpp", options);
  std::vector<std::string> expected(c.copied.begin(), c.copied.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(copied_procedures(*program), expected);
  options.inline_leaf_calls = false;
  EXPECT_TRUE(copied_procedures(*gppl::compile_source(c.source, "test.gpp", options)).empty());
}

TEST_P(InlineCalls, TraceShowsTheCalls) {
  const Case& c = GetParam();
  std::ostringstream called_trace, copied_trace;
  const Outcome called = run_case(c, false, &called_trace), copied = run_case(c, true, &copied_trace);
  EXPECT_EQ(copied.lines, called.lines);
  EXPECT_EQ(copied_trace.str(), called_trace.str());
}

INSTANTIATE_TEST_SUITE_P(Posts, InlineCalls, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// An error inside a copied body names the same place as inside the procedure; the call depth is
// checked at the copy as at a call (error 405).
TEST(InlineCallErrors, SamePositionAndDepth) {
  const std::string source = R"(@init_post
  global numeric x
  global integer zero
endp
@divide
  x = 1 / zero
endp
@inner
  call @divide
endp
@t
  call @inner
endp
)";
  for (const int depth : {2, 3, 50}) {
    std::string messages[2];
    for (const bool copy : {false, true}) {
      gppl::CompileOptions options;
      options.inline_leaf_calls = copy;
      Post post(source, options);
      post.run->set_limits(1000, depth);
      post.run->start();
      try {
        post.call("@t");
        messages[copy] = "no error";
      } catch (const gppl::Error& e) {
        messages[copy] = e.what();
      }
    }
    EXPECT_EQ(messages[1], messages[0]) << "depth " << depth;
    // Two frames (@t, @inner) are open at the call of @divide: the limit 2 stops it there.
    EXPECT_NE(messages[0].find(depth == 2 ? "error 405" : "error"), std::string::npos) << messages[0];
  }
}

}  // namespace
