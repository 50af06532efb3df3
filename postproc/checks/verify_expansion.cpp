// The toolpath side of `postproc verify`: the posted commands kept on disk, then run in machine
// order with subroutine calls and loops expanded (ExpectedMotion in postproc/checks/verify.hpp).
//
// SolidCAM writes the main program first and the subroutine bodies after it, so nothing can be
// expanded before the job ends. The commands go to two spools (temporary files, two blocks of a
// mebibyte in memory each): the main program, and the bodies, each body one contiguous range of
// records. Memory then holds, whatever the job length: the spools' blocks, a (first, end) pair per
// subroutine label, and the frames of the calls being run (at most 64, each with its open loops).
#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "postproc/checks/verify_modeller.hpp"
#include "prp/filters/command_spool.hpp"
#include "toolpath/value.hpp"

namespace postproc::verify {
namespace {

using toolpath::Command;

// A count (proc_count, loop_count, label) of a command; `fallback` when absent or not a number.
// A value beyond 1e15 (or not finite) is no count: an error naming it, not an undefined conversion.
std::int64_t count_or(const Command& c, std::string_view name, std::int64_t fallback) {
  const std::optional<double> n = number(c, name);
  if (!n) return fallback;
  const double x = *n;
  if (!(std::abs(x) <= 1e15))
    throw std::runtime_error(fmt::format("command #{} {}: {} {} is not a count", c.index, c.name, name, x));
  return static_cast<std::int64_t>(x);
}

constexpr std::size_t kMaxDepth = 64;  // frames, the main program's included
constexpr std::size_t kMaxOpenLoops = 64;  // per frame: @loop without @end_loop must not grow memory

// Records [first, end) of a spool.
struct Range {
  std::int64_t first = 0;
  std::int64_t end = 0;
};

// Walks the main program, running each called body (and each loop) as often as it repeats. Every
// frame remembers its place as a spool offset; the spool is moved there only when another frame
// read last, so a body is read straight through like the main program.
class Expansion final : public MotionSource {
public:
  Expansion(const prp::MachineParameters& machine, const machines::VerifyProfile& profile, prp::CommandSpool& main,
            prp::CommandSpool& bodies, const std::map<std::int64_t, Range>& ranges, std::uint64_t max_commands)
      : bodies_(bodies), ranges_(ranges), model_(machine, profile, pending_), budget_(max_commands) {
    frames_.push_back({&main, {0, main.end()}, 0, 1, {}});
  }

  bool next(Motion& out) override {
    while (pending_.empty()) {
      if (!step()) return false;
    }
    out = std::move(pending_.front());
    pending_.pop_front();
    return true;
  }

private:
  struct Loop {
    std::int64_t start;  // offset of the first record inside the loop
    std::int64_t remaining;
  };
  struct Frame {
    prp::CommandSpool* spool;
    Range range;
    std::int64_t pos;      // offset of the next record
    std::int64_t repeats;  // runs left, this one included
    std::vector<Loop> loops;
  };

  bool step() {
    if (frames_.empty()) return false;
    Frame& f = frames_.back();
    if (f.pos >= f.range.end) {
      if (--f.repeats > 0) {
        f.pos = f.range.first;
        f.loops.clear();
      } else {
        frames_.pop_back();
      }
      return true;
    }
    if (budget_ == 0)
      throw std::runtime_error(fmt::format("the calls and loops run more than {} commands: a runaway count?", run_));
    --budget_;
    ++run_;
    if (f.spool->position() != f.pos) f.spool->seek(f.pos);
    if (!f.spool->read(command_)) throw std::runtime_error("verify: the temporary file of posted commands was cut short");
    f.pos = f.spool->position();
    const Command& c = command_;
    if (is(c, "@loop")) {
      if (f.loops.size() >= kMaxOpenLoops)
        throw std::runtime_error(fmt::format("command #{} @loop: loops nest deeper than {}", c.index, kMaxOpenLoops));
      f.loops.push_back({f.pos, std::max<std::int64_t>(1, count_or(c, "loop_count", 1))});
    } else if (is(c, "@end_loop")) {
      if (!f.loops.empty() && --f.loops.back().remaining > 0) {
        f.pos = f.loops.back().start;
      } else if (!f.loops.empty()) {
        f.loops.pop_back();
      }
    } else if (is(c, "@call_proc")) {
      const std::int64_t label = count_or(c, "label", 0);
      auto body = ranges_.find(label);
      if (body == ranges_.end())
        throw std::runtime_error(fmt::format("command #{} @call_proc: subroutine {} has no body", c.index, label));
      if (frames_.size() >= kMaxDepth)
        throw std::runtime_error(fmt::format("command #{} @call_proc: calls nest deeper than {}", c.index, kMaxDepth));
      const std::int64_t count = std::max<std::int64_t>(1, count_or(c, "proc_count", 1));
      frames_.push_back({&bodies_, body->second, body->second.first, count, {}});  // `f` is invalid from here
    } else {
      model_.command(c);
    }
    return true;
  }

  prp::CommandSpool& bodies_;
  const std::map<std::int64_t, Range>& ranges_;
  std::deque<Motion> pending_;  // the motion of one command (a drill cycle's hole: a few moves)
  CommandModel model_;
  std::vector<Frame> frames_;
  Command command_;  // the record read last (its buffers are reused)
  std::uint64_t budget_;   // commands that may still run
  std::uint64_t run_ = 0;  // commands run
};

}  // namespace

struct ExpectedMotion::Data {
  Data(const prp::MachineParameters& m, const machines::VerifyProfile& p) : machine(m), profile(p) {}
  const prp::MachineParameters& machine;
  machines::VerifyProfile profile;
  prp::CommandSpool main;    // the main program, in stream order
  prp::CommandSpool bodies;  // the bodies, each a contiguous range
  std::map<std::int64_t, Range> ranges;
  Range* current = nullptr;  // the body being read (nullptr: the main program)
  Command kept;              // what is spooled of a command: name, index, parameters
};

ExpectedMotion::ExpectedMotion(const prp::MachineParameters& machine, const machines::VerifyProfile& profile)
    : data_(std::make_unique<Data>(machine, profile)) {}
ExpectedMotion::~ExpectedMotion() = default;

void ExpectedMotion::add(const Command& command) {
  Data& d = *data_;
  if (is(command, "@proc")) {  // a label defined again: the later body replaces the earlier one
    d.current = &d.ranges[count_or(command, "label", 0)];
    *d.current = {d.bodies.end(), d.bodies.end()};
    return;
  }
  if (is(command, "@end_proc")) {
    d.current = nullptr;
    return;
  }
  if (is(command, "@message")) return;
  d.kept.name = command.name;
  d.kept.index = command.index;
  d.kept.parameters = command.parameters;  // assignment reuses the buffers of the previous command
  if (d.current) {
    d.bodies.write(d.kept);
    d.current->end = d.bodies.end();
  } else {
    d.main.write(d.kept);
  }
}

std::unique_ptr<MotionSource> ExpectedMotion::motion(std::uint64_t max_commands) {
  return std::make_unique<Expansion>(data_->machine, data_->profile, data_->main, data_->bodies, data_->ranges,
                                     max_commands);
}

}  // namespace postproc::verify
