// The tree-walking interpreter over a compiled Program (compiled.hpp), with the G-code builder,
// the dialog and the non-interactive messages of section 10.
#pragma once

#include <ostream>
#include <set>
#include <streambuf>
#include <string>
#include <vector>

#include "machines/pikocnc/script/compiled.hpp"
#include "machines/pikocnc/script/dialog.hpp"
#include "machines/pikocnc/script/gcode_builder.hpp"
#include "machines/pikocnc/script/script.hpp"

namespace pikocnc::script {

// --describe-args ends the run at ArgEdit, successfully.
struct DescribedStop {};

class Interpreter {
public:
  Interpreter(const Program& program, const RunInputs& inputs, std::ostream& gcode, std::ostream& diagnostics);
  RunResult run();

private:
  enum class Flow { Normal, Break, Continue, Exit };
  struct Frame {
    std::vector<Value> slots;
    std::vector<Value*> refs;  // var parameters
  };

  Flow exec(const Stmt& s);
  Flow exec_list(const std::vector<std::unique_ptr<Stmt>>& list);
  Value eval(const Expr& e);
  Value* ref(const Expr& e);
  Value call(const Expr& e);
  Value builtin(const Expr& e);  // builtins_run.cpp
  Value make_default(const Type& t) const;
  void step(Pos at);
  bool condition(const Expr& e);
  [[noreturn]] void fail(Pos at, const std::string& message) const;

  // Where G-code goes when --describe-args asks for the dialog instead.
  struct NullBuffer : std::streambuf {
    int overflow(int c) override { return c; }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
  };
  const Program& program_;
  const RunInputs& inputs_;
  std::ostream& out_;
  NullBuffer null_buffer_;
  std::ostream null_{&null_buffer_};
  std::ostream& diag_;
  GcodeBuilder builder_;
  Dialog dialog_;
  std::vector<Value> globals_;
  Frame* frame_ = nullptr;
  std::uint32_t depth_ = 0;
  std::uintptr_t stack_base_ = 0;  // address of a local in run(): deep expressions inside deep
                                   // recursion are stopped by stack use, not only by call depth
  std::uint64_t steps_ = 0;
  std::vector<double> predefined_;
  std::vector<bool> predefined_given_, predefined_read_;
  std::size_t next_answer_ = 0;
};

}  // namespace pikocnc::script
