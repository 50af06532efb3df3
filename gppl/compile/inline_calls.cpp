// Calls of small leaf procedures copied in place. A post calls helpers such as `@forced_g` on
// every motion; a call costs the interpreter a frame, the trace and line-function tests and a
// nested instruction loop (about a hundred instructions), more than the two tests such a helper
// makes. The copy runs as the call would: it starts with an InlineLeaf instruction, which checks
// the call depth as a call does and, when a trace is written, runs the procedure as a real call
// (the trace shows it) and skips the copy; a `return` in the body jumps past the copy.
//
// Only procedures that read nothing of a frame are copied: no parameters or locals, no generate
// statements (an output line names the procedure it comes from), no trace, input or print
// statements, and no calls (copies stay flat). A post that uses start_line/end_line keeps every
// call (the host follows each procedure's entry and exit). Copying procedures with a frame as
// well (locals, generate statements: `@arc_plane`) was measured and dropped: an instruction that
// opens the frame and one that closes it cost about what the call costs.
#include "gppl/compile/compiler.hpp"

namespace gppl {

namespace {

constexpr std::uint32_t kMaxCopied = 48;  // instructions of a copied body: keeps the code small

bool is_jump(OpCode op) { return op == OpCode::Jump || op == OpCode::JumpIfFalse || op == OpCode::LoopIfFalse; }

bool copyable(const Program& program, const Procedure& p) {
  if (!p.defined || p.parameter_count != 0 || p.frame_size != 0 || !p.locals.empty()) return false;
  if (p.end <= p.first || p.end - p.first > kMaxCopied || program.code[p.end - 1].op != OpCode::Return) return false;
  for (std::uint32_t i = p.first; i < p.end; ++i) {
    const Instruction& in = program.code[i];
    switch (in.op) {
      case OpCode::Nop:
      case OpCode::Assign:
      case OpCode::SetChange:
      case OpCode::SetActive:
      case OpCode::Abort:
      case OpCode::Exit:
      case OpCode::Return: break;
      case OpCode::Jump:
      case OpCode::JumpIfFalse:
      case OpCode::LoopIfFalse:
        if (in.a < p.first || in.a >= p.end) return false;  // never made by the code generator
        break;
      case OpCode::Call:
      case OpCode::InlineLeaf:
      case OpCode::Generate:
      case OpCode::Trace:
      case OpCode::Input:
      case OpCode::Print: return false;
    }
  }
  return true;
}

}  // namespace

void inline_leaf_calls(Program& program) {
  if (program.uses_line_functions) return;
  std::vector<bool> leaf(program.procedures.size());
  bool any = false;
  for (std::size_t p = 0; p < program.procedures.size(); ++p) any |= leaf[p] = copyable(program, program.procedures[p]);
  if (!any) return;

  const auto copied = [&](const Instruction& in) { return in.op == OpCode::Call && leaf[in.a]; };
  // Where each instruction of the old code lands: a copied call grows by its body less its final
  // Return (InlineLeaf takes the call's place).
  std::vector<std::uint32_t> moved(program.code.size() + 1);
  std::uint32_t at = 0;
  for (std::uint32_t i = 0; i < program.code.size(); ++i) {
    moved[i] = at;
    const Instruction& in = program.code[i];
    at += copied(in) ? program.procedures[in.a].end - program.procedures[in.a].first : 1;
  }
  moved[program.code.size()] = at;

  std::vector<Instruction> code;
  code.reserve(at);
  for (std::uint32_t i = 0; i < program.code.size(); ++i) {
    Instruction in = program.code[i];
    if (!copied(in)) {
      if (is_jump(in.op)) in.a = moved[in.a];
      code.push_back(in);
      continue;
    }
    const Procedure& callee = program.procedures[in.a];
    const auto start = std::uint32_t(code.size());
    const std::uint32_t after = start + (callee.end - callee.first);  // also where the final Return stood
    code.push_back(Instruction{OpCode::InlineLeaf, in.a, after, 0, in.pos});
    for (std::uint32_t k = callee.first; k + 1 < callee.end; ++k) {
      Instruction body = program.code[k];
      if (is_jump(body.op)) body.a = start + 1 + (body.a - callee.first);
      else if (body.op == OpCode::Return) body = Instruction{OpCode::Jump, after, 0, 0, body.pos};
      code.push_back(body);
    }
  }
  for (Procedure& p : program.procedures) {
    p.first = moved[p.first];
    p.end = moved[p.end];
  }
  program.code = std::move(code);
}

}  // namespace gppl
