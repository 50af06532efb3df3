// Statements and expressions at run time; routine calls with their frames; the step budget that
// stops runaway loops and the depth limit that stops runaway recursion (spec 2.6).
#include "machines/pikocnc/script/interpreter.hpp"

#include <fmt/format.h>

#include <pthread.h>

#include <cstdlib>
#include <exception>

#include "machines/pikocnc/script/builtins.hpp"
#include "machines/pikocnc/script/ops.hpp"

namespace pikocnc::script {

namespace {
// Stack the interpreter may use for nested script calls: 5 MB on a caller's thread (the usual
// main stack is 8 MB), most of its own 256 MB thread (run_script).
constexpr std::size_t kThreadStack = std::size_t(256) << 20;
thread_local std::uintptr_t stack_budget = 5u << 20;
}  // namespace

Interpreter::Interpreter(const Program& program, const RunInputs& inputs, std::ostream& gcode, std::ostream& diagnostics)
    : program_(program),
      inputs_(inputs),
      out_(gcode),
      diag_(diagnostics),
      builder_(inputs.describe_args ? null_ : gcode, inputs.crlf) {
  const auto& names = predefined_constants();
  predefined_.assign(names.size(), 0.0);
  predefined_given_.assign(names.size(), false);
  predefined_read_.assign(names.size(), false);
  for (const auto& [name, text] : inputs.constants) {
    const int index = find_predefined(name);
    if (index < 0) throw toolpath::InputError({program.file, 0, 0}, fmt::format("unknown constant `{}` (the predefined constants are MAT_SIZE_X ... RUN_CNT)", name));
    std::string t = text;
    for (char& c : t)
      if (c == ',') c = '.';
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (t.empty() || *end != '\0' || !std::isfinite(v))
      throw toolpath::InputError({program.file, 0, 0}, fmt::format("constant {}: `{}` is not a number", name, text));
    predefined_[std::size_t(index)] = v;
    predefined_given_[std::size_t(index)] = true;
  }
  const int run_cnt = find_predefined("RUN_CNT");
  if (!predefined_given_[std::size_t(run_cnt)]) predefined_[std::size_t(run_cnt)] = inputs.run_count;
  predefined_given_[std::size_t(run_cnt)] = true;  // RUN_CNT = 0 is meaningful, not a default to warn about
  if (predefined_[std::size_t(run_cnt)] != std::trunc(predefined_[std::size_t(run_cnt)]))
    throw toolpath::InputError({program.file, 0, 0}, "RUN_CNT must be an integer");
}

void Interpreter::fail(Pos at, const std::string& message) const {
  throw toolpath::InputError({program_.file, at.line, at.column}, message);
}

void Interpreter::step(Pos at) {
  if (++steps_ > inputs_.max_steps)
    fail(at, fmt::format("runaway script: more than {} statements executed (an endless loop?)", inputs_.max_steps));
}

Value Interpreter::make_default(const Type& t) const {
  switch (t.kind) {
    case Kind::Float: return Value::real(0);
    case Kind::Boolean: return Value::boolean(false);
    case Kind::String: return Value::text({});
    case Kind::Record: {
      const Shape& s = program_.shapes[std::size_t(t.shape)];
      Value v;
      v.kind = Kind::Record;
      for (const auto& f : s.field_types) v.items.push_back(make_default(f));
      return v;
    }
    case Kind::Array: {
      const Shape& s = program_.shapes[std::size_t(t.shape)];
      Value v;
      v.kind = Kind::Array;
      v.items.assign(std::size_t(s.count), make_default(s.element));
      return v;
    }
    default: return Value::integer(0);
  }
}

RunResult Interpreter::run() {
  RunResult result;
  const char base_marker = 0;
  stack_base_ = reinterpret_cast<std::uintptr_t>(&base_marker);
  for (const auto& t : program_.globals) globals_.push_back(make_default(t));
  Frame top;
  frame_ = &top;
  try {
    for (const auto& [slot, init] : program_.const_inits) globals_[std::size_t(slot)] = eval(*init);
    exec(*program_.main);
  } catch (const DescribedStop&) {
    result.described = true;
  } catch (const OpError& e) {
    fail({}, e.what());  // positions are added where the error arises; this is a fallback
  }
  if (inputs_.describe_args && !result.described) {
    // The dialog is never opened: describe what it would show.
    diag_ << fmt::format("{}: warning: the script never calls ArgEdit; describing its arguments at the end of the run\n", program_.file);
    try {
      dialog_.apply({});
    } catch (const OpError& e) {
      fail({}, e.what());
    }
    out_ << dialog_.json();
    result.described = true;
  }
  builder_.flush();
  if (!dialog_.edited() && !inputs_.args.empty())
    diag_ << fmt::format("{}: warning: the script never calls ArgEdit, so the argument overrides were ignored\n", program_.file);
  std::string defaulted;
  const auto& names = predefined_constants();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (predefined_read_[i] && !predefined_given_[i]) defaulted += (defaulted.empty() ? "" : ", ") + std::string(names[i].name);
  if (!defaulted.empty())
    diag_ << fmt::format("{}: note: constants read with their default 0 (give them with --const or [constants]): {}\n", program_.file, defaulted);
  result.lines = builder_.lines();
  result.steps = steps_;
  return result;
}

Interpreter::Flow Interpreter::exec_list(const std::vector<std::unique_ptr<Stmt>>& list) {
  for (const auto& s : list) {
    const Flow f = exec(*s);
    if (f != Flow::Normal) return f;
  }
  return Flow::Normal;
}

bool Interpreter::condition(const Expr& e) {
  const Value v = eval(e);
  try {
    return truthy(v);
  } catch (const OpError& x) {
    fail(e.pos, x.what());
  }
}

Interpreter::Flow Interpreter::exec(const Stmt& s) {
  step(s.pos);
  switch (s.kind) {
    case St::Empty: return Flow::Normal;
    case St::Assign: {
      Value v = eval(*s.value);
      *ref(*s.target) = std::move(v);
      return Flow::Normal;
    }
    case St::Call: eval(*s.value); return Flow::Normal;
    case St::Block: return exec_list(s.body);
    case St::If:
      if (condition(*s.value)) return exec(*s.body[0]);
      return s.body.size() > 1 ? exec(*s.body[1]) : Flow::Normal;
    case St::Case: {
      const Value sel = eval(*s.value);
      for (std::size_t arm = 0; arm < s.labels.size(); ++arm)
        for (const auto& label : s.labels[arm]) {
          bool match = false;
          try {
            match = apply_binary(Bin::Eq, sel, label->literal).b;
          } catch (const OpError& e) {
            fail(label->pos, e.what());
          }
          if (match) return exec(*s.body[arm]);
        }
      return s.has_else ? exec(*s.body.back()) : Flow::Normal;
    }
    case St::ForUp:
    case St::ForDown: {
      const std::int64_t from = eval(*s.value).i, to = eval(*s.limit).i;
      const std::int64_t dir = s.kind == St::ForUp ? 1 : -1;
      for (std::int64_t i = from; dir > 0 ? i <= to : i >= to; i += dir) {
        *ref(*s.target) = Value::integer(i);
        const Flow f = exec(*s.body[0]);
        if (f == Flow::Break) break;
        if (f == Flow::Exit) return f;
      }
      return Flow::Normal;
    }
    case St::While:
      while (condition(*s.value)) {
        step(s.pos);
        const Flow f = exec(*s.body[0]);
        if (f == Flow::Break) break;
        if (f == Flow::Exit) return f;
      }
      return Flow::Normal;
    case St::Repeat:
      for (;;) {
        step(s.pos);
        const Flow f = exec_list(s.body);
        if (f == Flow::Break) break;
        if (f == Flow::Exit) return f;
        if (condition(*s.value)) break;
      }
      return Flow::Normal;
    case St::Break: return Flow::Break;
    case St::Continue: return Flow::Continue;
    case St::Exit: return Flow::Exit;
  }
  return Flow::Normal;
}

Value* Interpreter::ref(const Expr& e) {
  switch (e.op) {
    case Op::Global: return &globals_[std::size_t(e.slot)];
    case Op::Local: return &frame_->slots[std::size_t(e.slot)];
    case Op::RefParam: return frame_->refs[std::size_t(e.slot)];
    case Op::Field: return &ref(*e.kids[0])->items[std::size_t(e.slot)];
    case Op::Index: {
      Value* base = ref(*e.kids[0]);
      const std::int64_t i = eval(*e.kids[1]).i;
      const Shape& shape = program_.shapes[std::size_t(e.kids[0]->type.shape)];
      if (i < shape.low || i >= shape.low + shape.count)
        fail(e.pos, fmt::format("index {} is outside the array's bounds {}..{}", i, shape.low, shape.low + shape.count - 1));
      return &base->items[std::size_t(i - shape.low)];
    }
    default: fail(e.pos, "internal error: not a variable");
  }
}

Value Interpreter::eval(const Expr& e) {
  switch (e.op) {
    case Op::Literal: return e.literal;
    case Op::Global:
    case Op::Local:
    case Op::RefParam:
    case Op::Field:
    case Op::Index: return *ref(e);
    case Op::Predefined: {
      predefined_read_[std::size_t(e.slot)] = true;
      const double v = predefined_[std::size_t(e.slot)];
      return e.type.kind == Kind::Integer ? Value::integer(std::int64_t(v)) : Value::real(v);
    }
    case Op::Call: return call(e);
    case Op::Builtin: return builtin(e);
    case Op::Unary:
      try {
        return apply_unary(Un(e.sub), eval(*e.kids[0]));
      } catch (const OpError& x) {
        fail(e.pos, x.what());
      }
    case Op::Binary: {
      const Bin op = Bin(e.sub);
      Value a = eval(*e.kids[0]);
      // and/or on Booleans short-circuit, as Delphi's default {$B-}.
      if (a.kind == Kind::Boolean && ((op == Bin::And && !a.b) || (op == Bin::Or && a.b))) return a;
      try {
        return apply_binary(op, a, eval(*e.kids[1]));
      } catch (const OpError& x) {
        fail(e.pos, x.what());
      }
    }
    case Op::Convert:
      try {
        return convert_to(eval(*e.kids[0]), e.type);
      } catch (const OpError& x) {
        fail(e.pos, x.what());
      }
  }
  return {};
}

Value Interpreter::call(const Expr& e) {
  const Routine& r = program_.routines[std::size_t(e.slot)];
  if (depth_ >= inputs_.max_call_depth)
    fail(e.pos, fmt::format("runaway recursion: more than {} nested calls (calling `{}`)", inputs_.max_call_depth, r.name));
  step(e.pos);
  const char marker = 0;
  const std::uintptr_t here = reinterpret_cast<std::uintptr_t>(&marker);
  const std::uintptr_t used = here > stack_base_ ? here - stack_base_ : stack_base_ - here;
  if (used > stack_budget)
    fail(e.pos, fmt::format("runaway recursion: the script's calls nest too deeply (calling `{}`)", r.name));
  Frame frame;
  frame.slots.reserve(r.locals.size());
  for (const auto& t : r.locals) frame.slots.push_back(make_default(t));
  frame.refs.assign(r.locals.size(), nullptr);
  for (std::size_t i = 0; i < e.kids.size(); ++i) {
    const std::size_t slot = std::size_t(r.first_param) + i;
    if (r.by_ref[i]) frame.refs[slot] = ref(*e.kids[i]);
    else frame.slots[slot] = eval(*e.kids[i]);
  }
  Frame* saved = frame_;
  ++depth_;
  frame_ = &frame;
  struct Restore {
    Interpreter& in;
    Frame* saved;
    ~Restore() {
      in.frame_ = saved;
      --in.depth_;
    }
  } restore{*this, saved};
  for (const auto& [slot, init] : r.const_inits) frame.slots[std::size_t(slot)] = eval(*init);
  exec(*r.body);
  return r.is_function ? std::move(frame.slots[0]) : Value{};
}

// The interpreter runs on a thread of its own with a large stack, so that the 1000 nested calls
// the limit promises fit whatever the build (sanitizer frames are several times larger); only the
// pages a script touches are ever committed.
RunResult run_script(const Program& program, const RunInputs& inputs, std::ostream& gcode, std::ostream& diagnostics) {
  struct Job {
    const Program& program;
    const RunInputs& inputs;
    std::ostream& gcode;
    std::ostream& diagnostics;
    pthread_t caller;
    RunResult result;
    std::exception_ptr error;
  } job{program, inputs, gcode, diagnostics, pthread_self(), {}, nullptr};
  auto body = [](void* p) -> void* {
    Job& j = *static_cast<Job*>(p);
    if (pthread_self() != j.caller) stack_budget = kThreadStack - (std::size_t(16) << 20);
    try {
      Interpreter interpreter(j.program, j.inputs, j.gcode, j.diagnostics);
      j.result = interpreter.run();
    } catch (...) {
      j.error = std::current_exception();
    }
    return nullptr;
  };
  pthread_attr_t attr;
  pthread_t thread;
  bool started = pthread_attr_init(&attr) == 0 && pthread_attr_setstacksize(&attr, kThreadStack) == 0 &&
                 pthread_create(&thread, &attr, body, &job) == 0;
  pthread_attr_destroy(&attr);
  if (started) pthread_join(thread, nullptr);
  else body(&job);  // no thread: run here, with the smaller budget still protecting the stack
  if (job.error) std::rethrow_exception(job.error);
  return job.result;
}

}  // namespace pikocnc::script
