// The line loop and the dispatcher: which code owns which words (section 2.2) and the order of
// execution inside a line (section 2.3). The steps themselves live in exec_*.cpp.
#include "machines/pikocnc/model/interpreter.hpp"

#include <fmt/format.h>

#include "machines/pikocnc/model/interpreter_detail.hpp"

namespace pikocnc {

Interpreter::Interpreter(std::istream& in, std::string file_name, Options options)
    : options_(std::move(options)),
      file_(std::move(file_name)),
      lines_(in, file_),
      diagnostics_(options_.diagnostic_limit),
      emitter_(options_.chord_tolerance),
      compensator_(file_, options_.arc_tolerance),
      restarts_left_(options_.m99_restarts) {
  emitter_.attach_nc_lines(options_.nc_lines_in_trace);
  emitter_.limit(options_.max_commands, file_);
  s_.bases = options_.work_offsets;
  s_.diameter = options_.lathe_diameter_default;
  s_.feed = options_.initial_feed;
  s_.spindle = options_.initial_spindle;
  for (std::size_t i = 0; i < 5; ++i) s_.tip[i] = s_.bases[0][i] + options_.start_position[i];
  recompute_program_position();
  if (options_.start_position[3] != 0) emitter_.use_a();
  if (options_.start_position[4] != 0) emitter_.use_b();
  emitter_.add("@start_of_file");
  const std::size_t slash = file_.find_last_of("/\\");
  emitter_.text("g_file_name", slash == std::string::npos ? file_ : file_.substr(slash + 1));
  emitter_.text("dialect", dialect_name(options_.dialect));
  emitter_.logical("inch_system", false);
}

void Interpreter::fail(std::size_t column, const std::string& message) const {
  throw toolpath::InputError({file_, line_, column}, message);
}

void Interpreter::warn(std::size_t column, std::string message) { diagnostics_.add(line_, column, std::move(message)); }

bool Interpreter::run() {
  std::string_view text;
  while (emitter_.empty()) {
    if (finished_) return false;
    if (!lines_.next(text)) {
      emitter_.set_line(0, {});
      if (!started_) diagnostics_.add(1, 1, "no program start `%` found: nothing is executed");
      finish("EOF");
      continue;
    }
    line_ = lines_.line_number();
    if (!started_) {
      if (is_percent_line(text)) {
        started_ = true;
        program_start_ = lines_.mark();
        emitter_.set_line(line_, text);
        emitter_.add("@start_program");
        const Axes5 w = work_position();
        emitter_.number("xpos", w[0]);
        emitter_.number("ypos", w[1]);
        emitter_.number("zpos", w[2]);
      }
      continue;
    }
    if (is_percent_line(text)) {
      warn(1, "`%` after the program start has no meaning: ignored");
      continue;
    }
    if (++executed_ > options_.max_executed_lines)
      fail(1, fmt::format("more than {} lines executed: runaway loop stopped", options_.max_executed_lines));
    lex_line(text, line_, block_, diagnostics_);
    emitter_.set_line(line_, text);
    execute(block_);
    if (compensator_.wants_preview()) preview_chain();
  }
  return true;
}

void Interpreter::preview_chain() {
  // Everything the lines ahead may change is kept and put back; the file is read again later.
  const State state = s_;
  const std::vector<Loop> loops = loops_;
  const ncmodel::LineReader::Mark mark = lines_.mark();
  const std::size_t line = line_, executed = executed_, column = motion_column_;
  const int restarts = restarts_left_;
  const double pitch = thread_pitch_;
  const std::uint32_t changed_axes = transform_changed_axes_;
  const Emitter::Context context = emitter_.context();
  Diagnostics silent(0);
  std::swap(diagnostics_, silent);
  emitter_.mute(true);
  previewing_ = true;
  preview_ = ChainPreview{compensator_.plane()};
  try {
    std::string_view text;
    while (!preview_.done && lines_.next(text) && ++executed_ <= options_.max_executed_lines) {
      line_ = lines_.line_number();
      if (is_percent_line(text)) continue;
      lex_line(text, line_, block_, diagnostics_);
      execute(block_);
    }
  } catch (const toolpath::InputError&) {
    // the error is reported when the program really gets there
  }
  previewing_ = false;
  emitter_.mute(false);
  emitter_.restore(context);
  std::swap(diagnostics_, silent);
  s_ = state;
  loops_ = loops;
  lines_.seek(mark);
  line_ = line;
  executed_ = executed;
  motion_column_ = column;
  restarts_left_ = restarts;
  thread_pitch_ = pitch;
  transform_changed_axes_ = changed_axes;
  probe_protected_ = false;
  uncompensable_ = false;
  frame_dirty_ = true;
  compensator_.resolve_approach(preview_, emitter_);
}

void Interpreter::finish(std::string_view end_code) {
  if (previewing_) {  // running ahead: the program ends the chain
    preview_.end();
    return;
  }
  compensator_.stop(emitter_);
  warn_open_loops();
  if (started_) {
    emitter_.add("@end_program");
    const Axes5 w = work_position();
    emitter_.number("xpos", w[0]);
    emitter_.number("ypos", w[1]);
    emitter_.number("zpos", w[2]);
    emitter_.text("end_code", end_code);
  }
  // G115 anywhere in the program switches the automatic approach off, also in lines never executed.
  std::string_view text;
  Block rest;
  while (!g115_seen_ && end_code != "EOF" && lines_.next(text)) {
    lex_line(text, lines_.line_number(), rest, quiet_);
    for (std::size_t i = 0; i < rest.code_count; ++i)
      if (const CodeInfo* info = find_code(rest.codes[i], options_.dialect); info && info->op == Op::G115) g115_seen_ = true;
  }
  emitter_.add("@end_of_file");
  emitter_.logical("auto_approach", !g115_seen_);
  finished_ = true;
}

// A G25 that no G125 closed: its body ran once, to wherever the program ended.
void Interpreter::warn_open_loops() {
  for (const Loop& l : loops_)
    diagnostics_.add(l.line, l.column, "G25 without a closing G125: the body runs once, to the end of the program");
}

void Interpreter::ResolvedDeleter::operator()(Resolved* r) const { delete r; }

void Interpreter::execute(const Block& block) {
  if (!resolved_) resolved_.reset(new Resolved);
  Resolved& r = *resolved_;
  r.reset();
  for (std::size_t i = 0; i < block.code_count; ++i) {
    const CodeWord& cw = block.codes[i];
    const CodeInfo* info = find_code(cw, options_.dialect);
    if (!info) {
      warn(cw.column, cw.dot_digits ? fmt::format("unknown code {}{}.{} ignored", cw.letter, cw.number, cw.dot)
                                    : fmt::format("unknown code {}{} ignored", cw.letter, cw.number));
      continue;
    }
    r.add(*info, cw);
  }
  for (const auto& [col, text] : r.conflicts) warn(col, text);
  // 10. units and lathe X mode apply to every word of their own line, so they come first
  if (r.has(Op::G20)) s_.inch = true;
  if (r.has(Op::G21)) s_.inch = false;
  if (r.has(Op::G7)) s_.diameter = true;
  if (r.has(Op::G8)) s_.diameter = false;
  Words w(block, r, s_.inch ? 25.4 : 1.0, s_.diameter);

  // 1. comment text; 2. loop start
  if (block.has_comment && options_.comments_as_messages && !r.has(Op::G120)) {
    emitter_.add("@message");
    emitter_.text("message", block.comment);
  }
  if (r.has(Op::G25)) {
    if (!w.has('R')) fail(r.column(Op::G25), "G25 needs R (the number of passes)");
    double count = w.raw('R');
    if (!(count <= options_.max_loop_count))
      fail(w.col('R'), fmt::format("G25 R{}: expected a number of passes up to {}", count, options_.max_loop_count));
    if (count < 1) {
      warn(w.col('R'), "G25 R below 1: the body runs once");
      count = 1;
    }
    loops_.push_back({lines_.mark(), static_cast<long long>(count), line_, r.column(Op::G25)});
  }
  // 3-17: settings, in the documented order (exec_settings.cpp); units first so that lengths convert
  const bool codes = !r.only_motion();
  if (codes || w.has('F') || w.has('S')) feed_and_spindle(r, w);
  if (codes || w.has('T')) tool_and_m_codes(r, w);
  if (codes) {
    misc_modes(r, w);
    offsets(r, w);
    transforms(r, w);
  }
  // 18. motion
  motion(r, w);
  if (r.has(Op::G98) && !r.cycle_in_line) {  // G98 takes the current Z as the travel height
    s_.clearance_z = s_.prog.z();
    s_.clearance_known = true;
  }
  // 19. stops and program end
  if (r.has(Op::M0) || r.has(Op::M1)) {
    emitter_.add("@halt_program");
    emitter_.logical("optional", r.has(Op::M1) && !r.has(Op::M0));
  }
  w.report_unused([this](std::size_t col, std::string text) { warn(col, std::move(text)); });
  if (r.has(Op::M30)) {
    finish("M30");
    return;
  }
  if (r.has(Op::M99)) {
    if (previewing_) {
      preview_.end();
    } else if (restarts_left_ > 0) {
      --restarts_left_;
      warn_open_loops();
      loops_.clear();
      lines_.seek(program_start_);
    } else {
      warn(r.column(Op::M99), options_.m99_restarts == 0
                                  ? std::string("M99 repeats the program without end on the machine: read once here")
                                  : fmt::format("M99 repeats the program without end on the machine: read {} times here",
                                                options_.m99_restarts + 1));
      finish("M99");
    }
    return;
  }
  // 20. loop end
  if (r.has(Op::G125)) {
    if (loops_.empty()) {
      warn(r.column(Op::G125), "G125 without an open G25 loop: ignored");
    } else if (--loops_.back().remaining > 0) {
      lines_.seek(loops_.back().body);
    } else {
      loops_.pop_back();
    }
  }
}

}  // namespace pikocnc
