// The structure bookkeeping that completes @end_proc / @end_loop.
#include <gtest/gtest.h>

#include "postproc/engine/structure.hpp"

namespace {

toolpath::Command make(const char* name, std::vector<toolpath::Parameter> parameters = {}) {
  toolpath::Command c;
  c.name = name;
  c.parameters = std::move(parameters);
  return c;
}

TEST(ProgramStructure, CompletesEndProcAndEndLoop) {
  postproc::ProgramStructure s;
  using toolpath::Value;
  auto call_job = make("@call_proc", {{"label", Value::make_integer(1)}});
  auto proc1 = make("@proc", {{"label", Value::make_integer(1)}});
  auto call_inner = make("@call_proc", {{"label", Value::make_integer(4)}});
  auto end1 = make("@end_proc");
  auto proc4 = make("@proc", {{"label", Value::make_integer(4)}});
  auto loop = make("@loop", {{"label", Value::make_integer(7)}, {"loop_count", Value::make_integer(3)}});
  auto end_loop = make("@end_loop");
  auto end4 = make("@end_proc");
  for (auto* c : {&call_job, &proc1, &call_inner, &end1, &proc4, &loop, &end_loop, &end4}) s.before(*c);
  EXPECT_EQ(*end1.find("label"), Value::make_integer(1));
  EXPECT_EQ(*end1.find("end_of_job"), Value::make_logical(true));
  EXPECT_EQ(*end4.find("label"), Value::make_integer(4));
  EXPECT_EQ(*end4.find("end_of_job"), Value::make_logical(false)) << "called from a subroutine, not a job";
  EXPECT_EQ(*loop.find("loop_level"), Value::make_integer(1));
  EXPECT_EQ(*end_loop.find("label"), Value::make_integer(7));
  EXPECT_EQ(*end_loop.find("loop_count"), Value::make_integer(3));
  EXPECT_FALSE(s.in_subroutine());
}

}  // namespace
