// Procedure activation (fresh locals, typed parameters, call depth) and the instruction loop
// (spec 5.5-5.9: if/else, while with an iteration budget, call, break, return, exit, abort).
#include <fmt/format.h>

#include "gppl/run/machine.hpp"

namespace gppl {

void Interpreter::State::calls_too_deep() const {
  fail(ErrorCode::StackOverflow, {},
       fmt::format("procedure calls nest deeper than {} levels (runaway recursion?)", max_call_depth));
}

Flow Interpreter::State::run(std::uint32_t procedure, std::uint32_t args_list, std::uint32_t arg_count) {
  const Procedure& proc = program.procedures[procedure];
  if (int(frames.size()) >= max_call_depth) [[unlikely]] calls_too_deep();
  const std::uint32_t base = stack_top;
  if (arg_count == 0 && proc.frame_size == 0) frames.push_back(Frame{procedure, base});  // most: nothing to set up
  else enter(proc, procedure, args_list, arg_count);
  if (trace != nullptr && !in_init && trace_level(procedure) >= 1)
    trace_enter(proc.name, int(frames.size()), trace_level(procedure));
  if (program.uses_line_functions) sink.procedure_boundary(procedure, true);  // body structure (start_line)
  const Flow flow = execute(procedure);
  if (program.uses_line_functions) sink.procedure_boundary(procedure, false);
  frames.pop_back();
  stack_top = base;
  return flow;
}

void Interpreter::State::enter(const Procedure& proc, std::uint32_t procedure, std::uint32_t args_list,
                               std::uint32_t arg_count) {
  // Arguments are evaluated in the caller's frame.
  const std::uint32_t first_arg = scratch_top;
  for (std::uint32_t i = 0; i < arg_count; ++i) eval(program.lists[args_list + i], push_scratch());
  const std::uint32_t base = stack_top;
  stack_top += proc.frame_size;
  if (stack.size() < stack_top) stack.resize(stack_top);
  for (const LocalVariable& l : proc.locals)
    for (std::uint32_t k = 0; k < l.cell_count; ++k) reset_cell(stack[base + l.offset + k], l.type);
  frames.push_back(Frame{procedure, base});
  for (std::uint32_t i = 0; i < arg_count; ++i) {
    const LocalVariable& l = proc.locals[i];
    const VarRef ref{true, i, l.offset, kNone, 0};
    assign(stack[base + l.offset], *scratch[first_arg + i], ChangeOverride::Compute, &ref);
  }
  scratch_top = first_arg;
}

Flow Interpreter::State::execute(std::uint32_t procedure) {
  std::uint32_t pc = program.procedures[procedure].first;
  const Instruction* const code = program.code.data();  // read once: `current` is stored on every step
  for (;;) {
    const Instruction& in = code[pc];
    current = &in;
    switch (in.op) {
      case OpCode::Nop: ++pc; break;
      case OpCode::Assign: {
        const VarRef& ref = program.refs[in.a];
        with_value(in.b, [&](const Value& x) { assign(element(ref), x, ChangeOverride::Compute, &ref); });
        ++pc;
        break;
      }
      case OpCode::SetChange:
      case OpCode::SetActive: {
        // The value is stored, not tested: 0 or 1 only (error 420), unlike a condition.
        bool x = false;
        with_value(in.b, [&](const Value& v) { x = v.type == Type::Logical ? v.logical : to_logical(v); });
        Cell& c = element(program.refs[in.a]);
        (in.op == OpCode::SetChange ? c.changed : c.active) = x;
        ++pc;
        break;
      }
      case OpCode::LoopIfFalse:
        if (++loop_iterations > max_loop_iterations)
          fail(ErrorCode::StackOverflow, {},
               fmt::format("WHILE loops ran more than {} iterations in one procedure run (runaway loop?)",
                           max_loop_iterations));
        [[fallthrough]];
      case OpCode::JumpIfFalse: pc = condition(in.b) ? pc + 1 : in.a; break;
      case OpCode::Jump: pc = in.a; break;
      case OpCode::Call: {
        const Flow flow = run(in.a, in.b, in.c);
        current = &in;
        if (flow != Flow::Normal) return flow;
        ++pc;
        break;
      }
      case OpCode::InlineLeaf:
        // The procedure's body follows (compile/inline_calls.cpp). A trace shows calls: then it
        // is one, and the copy is skipped.
        if (trace == nullptr) [[likely]] {
          if (int(frames.size()) >= max_call_depth) [[unlikely]] calls_too_deep();
          ++pc;
          break;
        } else {
          const Flow flow = run(in.a, 0, 0);
          current = &in;
          if (flow != Flow::Normal) return flow;
          pc = in.b;
          break;
        }
      case OpCode::Generate:
        generate(in.a, in.b);
        ++pc;
        break;
      case OpCode::Trace: {
        Value& v = push_scratch();
        eval(in.b, v);
        const std::int64_t level = to_integer(v);
        pop_scratch();
        trace_statement(program.constants[in.a].text, level);
        ++pc;
        break;
      }
      case OpCode::Input:
        input(in.a);
        ++pc;
        break;
      case OpCode::Print:
        print(in.a, in.b);
        ++pc;
        break;
      case OpCode::Abort: return Flow::Abort;
      case OpCode::Exit: return Flow::Exit;
      case OpCode::Return: return Flow::Normal;
    }
  }
}

RunResult Interpreter::State::top_level(std::uint32_t procedure) {
  frames.clear();
  stack_top = 0;
  scratch_top = 0;
  argument_top = 0;
  loop_iterations = 0;
  current = nullptr;
  const Flow flow = run(procedure, 0, 0);
  current = nullptr;
  host_assigned.clear();
  switch (flow) {
    case Flow::Normal: return RunResult::Normal;
    case Flow::Exit: return RunResult::Exit;
    case Flow::Abort: break;
  }
  flush();  // abort keeps and flushes what was written (5.9)
  return RunResult::Abort;
}

}  // namespace gppl
