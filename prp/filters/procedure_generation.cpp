#include "prp/filters/procedure_generation.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "prp/filters/motion.hpp"

namespace prp {
namespace {

// A stand-in for a job in the main-program spool; its index is the job's number.
constexpr const char* kJobMarker = "\x01job";

using K = CommandKind;
constexpr KindSet kStructure =
    bit(K::proc) | bit(K::end_proc) | bit(K::call_proc) | bit(K::call_prms) | bit(K::loop) | bit(K::end_loop);
constexpr KindSet kToolChange = bit(K::change_tool) | bit(K::turn_change_tool) | bit(K::chng_tool_cnext);

void mix(std::uint64_t& hash, double v) {
  std::uint64_t bits;
  std::memcpy(&bits, &v, 8);
  for (int i = 0; i < 8; ++i) {
    hash ^= (bits >> (8 * i)) & 0xffu;
    hash *= 1099511628211u;  // FNV-1a
  }
}

constexpr std::uint64_t kHashStart = 14695981039346656037u;

// A cycle's point list, hashed to find the cycles that share one.
void add_point(auto& cycle, const toolpath::Command& point) {
  ++cycle.points;
  for (const char* axis : {"xpos", "ypos", "zpos"}) mix(cycle.hash, number(point, axis).value_or(0.0));
}

void end_cycle(auto& cycle) { mix(cycle.hash, static_cast<double>(cycle.points)); }

// A procedure body runs after the main program has changed to later tools, so its @start_of_job
// names the job's own tool (a parameter @start_of_job has, gpptool 6.1) when the toolpath left it out.
void add_tool_number(toolpath::Command& start, const auto& job) {
  if (job.tool_number && !start.find("tool_number")) start.set("tool_number", *job.tool_number);
}

}  // namespace

bool ProcedureGeneration::needed(const MachineParameters& params) {
  const std::string& g = params.text("gen_procs");
  return toolpath::iequals(g, "Y") || toolpath::iequals(g, "C");
}

ProcedureGeneration::ProcedureGeneration(toolpath::CommandSource& input, const MachineParameters& params)
    : input_(input),
      mode_(params.text("gen_procs")),
      drill_proc_(params.logical("drill_proc")),
      range_(procedure_numbers(params)),
      first_label_(range_.dflt.value_or(range_.min.value_or(1))) {}

ProcedureGeneration::ProcedureGeneration(toolpath::CommandSource& input, const MachineParameters& params,
                                         JobForecast&& forecast)
    : ProcedureGeneration(input, params) {
  main_ = std::move(forecast.main);
  jobs_ = std::move(forecast.jobs);
  cycles_ = std::move(forecast.cycles);
  last_label_ = forecast.last_label;
  forecast_ = true;
  phase_ = Phase::Main;
}

std::optional<JobForecast> ProcedureGeneration::forecast(toolpath::CommandSource& skimmed,
                                                         const MachineParameters& params) {
  ProcedureGeneration pass(skimmed, params);
  pass.forecasting_ = true;
  if (!pass.collect() || !pass.shared_.empty()) return std::nullopt;
  for (const Job& job : pass.jobs_)
    if (!job.label) return std::nullopt;
  // The bodies go where @end_of_file was: nothing of the main program may follow it.
  toolpath::Command c;
  CommandKind kind;
  bool after_end = false;
  while (pass.main_->read(c, kind)) {
    if (after_end) return std::nullopt;
    after_end = c.is_stream_command() && kind == K::end_of_file;
  }
  pass.main_->seek(0);
  JobForecast found;
  found.main = std::move(pass.main_);
  found.jobs = std::move(pass.jobs_);
  found.cycles = std::move(pass.cycles_);
  found.last_label = pass.last_label_;
  return found;
}

bool ProcedureGeneration::next_with_kind(toolpath::Command& out, CommandKind& kind) {
  // The phases that last: a structured toolpath passing through, the bodies of two passes.
  if (phase_ == Phase::Through) return input_.next(out, kind);
  if (phase_ == Phase::Live) return next_live(out, kind);
  return produce(out, kind);
}

bool ProcedureGeneration::produce(toolpath::Command& out, CommandKind& kind) {
  if (phase_ == Phase::Collect) phase_ = collect() ? Phase::Main : Phase::PassThrough;
  switch (phase_) {
    case Phase::PassThrough: {
      if (main_ && main_->read(out, kind)) return true;
      main_.reset();
      if (has_held_) {
        has_held_ = false;
        swap(out, held_);
        kind = command_kind(out);
        return true;
      }
      phase_ = Phase::Through;
      return input_.next(out, kind);
    }
    case Phase::Through: return input_.next(out, kind);
    case Phase::Main: return next_main(out, kind);
    case Phase::Body: return next_body(out, kind);
    case Phase::Points: return next_points(out, kind);
    case Phase::Live: return next_live(out, kind);
    default: return false;
  }
}

// The queue holds the few commands made here (calls, brackets) and a job's tool changes.
bool ProcedureGeneration::pop_queue(toolpath::Command& out, CommandKind& kind) {
  if (queue_.empty()) return false;
  swap(out, queue_.front());
  queue_.pop_front();
  kind = command_kind(out);
  return true;
}

bool ProcedureGeneration::collect() {
  main_.emplace();
  if (!forecasting_) bodies_.emplace();
  toolpath::Command c;
  bool in_job = false, leading = false, in_cycle = false;
  // The tool in the spindle: a job without tool changes of its own works with it. SolidCAM sends a
  // job's tool change before its @start_of_job (docs/parity.md, "Command order").
  std::optional<toolpath::Value> current_tool;
  Job job;
  Cycle cycle;
  K kind;
  while (input_.next(c, kind)) {
    if (c.is_stream_command() && has(kStructure, kind)) {
      if (jobs_.empty() && !in_job) {  // a structured toolpath: hand it on as it is
        swap(held_, c);
        has_held_ = true;
        main_->seek(0);
        bodies_.reset();
        return false;
      }
      if (forecasting_) return false;  // the full pass reports it
      throw StreamError(c, "the toolpath mixes inline jobs with procedures or loops, so gen_procs cannot "
                           "restructure it");
    }
    if (!in_job) {
      if (c.is_stream_command() && kind == K::start_of_job) {
        job = Job{.index = c.index, .first_cycle = cycles_.size(), .label = std::nullopt, .tool_number = current_tool};
        toolpath::Command marker;
        marker.name = kJobMarker;
        marker.index = jobs_.size();
        main_->write(marker, K::other);
        if (forecasting_) main_->write(c, kind);  // the job's head
        else job.offset = bodies_->write(c, kind);
        in_job = leading = true;
      } else {
        if (c.is_stream_command() && has(kToolChange, kind))
          if (const toolpath::Value* t = c.find("tool_number")) current_tool = *t;
        main_->write(c, kind);
      }
      continue;
    }
    const std::int64_t at = forecasting_ ? 0 : bodies_->write(c, kind);
    if (!c.is_stream_command()) continue;
    // Turning geometry bodies share the label space of subroutines (a cycle's start_line/end_line
    // names its body by label): the jobs' subroutines take other numbers.
    if (kind == K::turning || (kind == K::other && (toolpath::iequals(c.name, "@turn_proc") ||
                                                    toolpath::iequals(c.name, "@thread"))))
      if (auto l = number(c, "label"); l && *l > 0) geometry_labels_.insert(static_cast<std::int64_t>(*l));
    if (leading && has(kToolChange, kind)) {  // the other order: the job's tool changes open it
      if (const toolpath::Value* t = c.find("tool_number"); t && job.tools == 0) job.tool_number = current_tool = *t;
      ++job.tools;
      if (forecasting_) main_->write(c, kind);  // the job's head
      continue;
    }
    if (has(kToolChange, kind))
      if (const toolpath::Value* t = c.find("tool_number")) current_tool = *t;
    leading = false;
    if (kind == K::drill) {
      cycle = Cycle{};
      cycle.index = c.index;
      cycle.hash = kHashStart;
      in_cycle = true;
    } else if (in_cycle && kind == K::drill_point) {
      if (cycle.points == 0) cycle.points_offset = at;
      add_point(cycle, c);
    } else if (in_cycle && kind == K::end_drill) {
      in_cycle = false;
      end_cycle(cycle);
      cycles_.push_back(cycle);
      ++job.cycles;
    } else if (kind == K::end_of_job) {
      in_cycle = false;  // a cycle without @end_drill is never shared
      job.end = forecasting_ ? 0 : bodies_->end();
      jobs_.push_back(job);
      in_job = false;
    }
  }
  if (in_job) {  // the input ended inside a job: the job ends there
    job.end = forecasting_ ? 0 : bodies_->end();
    jobs_.push_back(job);
  }
  assign_labels();
  main_->seek(0);
  return true;
}

void ProcedureGeneration::assign_labels() {
  std::map<std::pair<std::uint64_t, std::size_t>, std::vector<std::size_t>> lists;
  if (drill_proc_)
    for (std::size_t i = 0; i < cycles_.size(); ++i)
      if (cycles_[i].points > 0) lists[{cycles_[i].hash, cycles_[i].points}].push_back(i);
  for (auto& [key, owners] : lists)
    if (owners.size() > 1) shared_.push_back(owners.front());
  std::sort(shared_.begin(), shared_.end());

  std::int64_t label = first_label_;
  auto take = [&](std::size_t index_for_errors) {
    while (geometry_labels_.count(label)) ++label;
    if (!range_.contains(label)) {
      toolpath::Command at;
      at.name = "@proc";
      at.index = index_for_errors;
      throw StreamError(at, fmt::format("procedure label {} is outside proc_num_min .. proc_num_max ({} .. {})", label,
                                        range_.min.value_or(0), range_.max.value_or(0)));
    }
    return label++;
  };
  auto is_shared = [&](std::size_t c) {
    return cycles_[c].points > 0 && lists.count({cycles_[c].hash, cycles_[c].points}) &&
           lists[{cycles_[c].hash, cycles_[c].points}].size() > 1;
  };
  for (std::size_t j = 0; j < jobs_.size(); ++j) {
    bool calls = false;
    for (std::size_t c = jobs_[j].first_cycle; c < jobs_[j].first_cycle + jobs_[j].cycles; ++c) calls |= is_shared(c);
    if (toolpath::iequals(mode_, "Y") || !calls) jobs_[j].label = take(jobs_[j].index);
  }
  for (std::size_t owner : shared_) {
    const std::int64_t l = take(cycles_[owner].index);
    for (std::size_t c : lists[{cycles_[owner].hash, cycles_[owner].points}]) cycles_[c].label = l;
  }
  last_label_ = label - 1;
}

void ProcedureGeneration::call(toolpath::Command& out, std::int64_t label, const toolpath::Command* job) {
  if (job) {
    out = *job;  // a job's call carries the job's parameters (gpptool 2.8)
    out.trace.clear();
    if (const toolpath::Value* name = job->find("job_name")) out.set("message", toolpath::Value::make_string(name->text));
  } else {
    out.clear();
  }
  out.name = "@call_proc";
  out.depth = 1;
  out.set("label", toolpath::Value::make_integer(label));
  out.set("proc_count", toolpath::Value::make_integer(1));
}

void ProcedureGeneration::bracket(toolpath::Command& out, const char* name, std::int64_t label,
                                  std::optional<bool> end_of_job, std::size_t index) {
  out.clear();
  out.name = name;
  out.index = index;
  out.set("label", toolpath::Value::make_integer(label));
  if (end_of_job) out.set("end_of_job", toolpath::Value::make_logical(*end_of_job));
}

// Queues the job's tool changes and its call, from its head (@start_of_job and the tool changes
// that open the job) where `head` reads next.
void ProcedureGeneration::queue_call(CommandSpool& head, const Job& job) {
  toolpath::Command start;
  head.read(start);
  add_tool_number(start, job);
  for (int i = 0; i < job.tools; ++i) {
    queue_.emplace_back();
    head.read(queue_.back());
  }
  queue_.emplace_back();
  call(queue_.back(), *job.label, &start);
}

// The forecast's main program is sent: the bodies come in now (main_ checks them from its start).
bool ProcedureGeneration::go_live(toolpath::Command& out, CommandKind& kind) {
  main_->seek(0);
  phase_ = Phase::Live;
  return next_live(out, kind);
}

bool ProcedureGeneration::next_main(toolpath::Command& out, CommandKind& kind) {
  if (pop_queue(out, kind)) return true;
  if (!main_->read(out, kind)) {
    if (forecast_) return go_live(out, kind);  // a main program without @end_of_file
    if (bodies_sent_ || !start_next_procedure()) {
      phase_ = Phase::Done;
      return false;
    }
    return produce(out, kind);
  }
  if (out.name == kJobMarker) {
    const Job& job = jobs_[out.index];
    if (forecast_) {  // the job's head follows its marker
      queue_call(*main_, job);
      return next_main(out, kind);
    }
    bodies_->seek(job.offset);
    if (!job.label) {  // stays inline (gen_procs = C and it calls a shared point list)
      body_inline_ = true;
      body_job_ = out.index;
      cycle_ = job.first_cycle;
      skip_tools_ = 0;
      phase_ = Phase::Body;
      return next_body(out, kind);
    }
    queue_call(*bodies_, job);
    return next_main(out, kind);
  }
  const bool stream = out.is_stream_command();
  if (stream && kind == K::start_of_file && last_label_ >= first_label_) {
    out.set("first_proc_number", toolpath::Value::make_integer(first_label_));
    out.set("last_proc_number", toolpath::Value::make_integer(last_label_));
    out.set("first_user_proc", toolpath::Value::make_integer(last_label_ + 1));
  }
  if (stream && kind == K::end_of_file && forecast_) {  // after the bodies
    swap(end_of_file_, out);
    has_end_of_file_ = true;
    return go_live(out, kind);
  }
  if (stream && kind == K::end_of_file && !bodies_sent_) {
    swap(end_of_file_, out);
    has_end_of_file_ = true;
    if (start_next_procedure()) return produce(out, kind);
    swap(out, end_of_file_);
    has_end_of_file_ = false;
  }
  return true;
}

// Queues the @proc of the next procedure body and switches to sending it; false when all are sent
// (the held @end_of_file, if any, is then queued and the main program resumes).
bool ProcedureGeneration::start_next_procedure() {
  while (next_proc_ < jobs_.size() && !jobs_[next_proc_].label) ++next_proc_;
  if (next_proc_ < jobs_.size()) {
    const Job& job = jobs_[next_proc_];
    body_inline_ = false;
    body_job_ = next_proc_++;
    cycle_ = job.first_cycle;
    skip_tools_ = -1;  // set once the @start_of_job is read
    bodies_->seek(job.offset);
    queue_.emplace_back();
    bracket(queue_.back(), "@proc", *job.label, std::nullopt, job.index);
    phase_ = Phase::Body;
    return true;
  }
  const std::size_t list = next_proc_ - jobs_.size();
  if (list < shared_.size()) {
    const Cycle& cycle = cycles_[shared_[list]];
    ++next_proc_;
    bodies_->seek(cycle.points_offset);
    queue_.emplace_back();
    bracket(queue_.back(), "@proc", *cycle.label, std::nullopt, cycle.index);
    phase_ = Phase::Points;
    return true;
  }
  bodies_sent_ = true;
  phase_ = Phase::Main;
  if (has_end_of_file_) {
    queue_.push_back(std::move(end_of_file_));
    has_end_of_file_ = false;
  }
  return !queue_.empty();
}

bool ProcedureGeneration::next_body(toolpath::Command& out, CommandKind& kind) {
  for (;;) {
    if (pop_queue(out, kind)) return true;
    const Job& job = jobs_[body_job_];
    if (bodies_->position() >= job.end || !bodies_->read(out, kind)) {
      if (body_inline_) {
        phase_ = Phase::Main;
        return next_main(out, kind);
      }
      queue_.emplace_back();
      bracket(queue_.back(), "@end_proc", *job.label, true, last_index_);
      if (!start_next_procedure()) phase_ = Phase::Main;
      continue;
    }
    last_index_ = out.index;
    if (!out.is_stream_command()) return true;
    if (skip_tools_ < 0) {  // the job's @start_of_job opens the body; its tool changes were sent in main
      skip_tools_ = job.tools;
      add_tool_number(out, job);
      return true;
    }
    if (skip_tools_ > 0) {
      --skip_tools_;
      continue;
    }
    if (skipping_points_) {
      if (kind == K::end_drill) skipping_points_ = false;
      if (kind == K::drill_point || kind == K::end_drill) continue;
    }
    if (kind == K::drill && cycle_ < job.first_cycle + job.cycles) {
      const Cycle& cycle = cycles_[cycle_++];
      if (cycle.label) {
        queue_.emplace_back();
        call(queue_.back(), *cycle.label, nullptr);
        queue_.back().index = out.index;
        skipping_points_ = true;
      }
    }
    return true;
  }
}

// The second pass of two: the main program has been sent from the forecast, which main_ now reads
// again from its start to check the job against it as the job streams in. A body is handed on as
// it comes, between its @proc and @end_proc; everything outside the bodies is the forecast's and
// is dropped once checked.
bool ProcedureGeneration::next_live(toolpath::Command& out, CommandKind& kind) {
  for (;;) {
    if (pop_queue(out, kind)) return true;
    if (bodies_sent_) {
      phase_ = Phase::Done;
      return false;
    }
    if (!input_.next(out, kind)) {
      end_live();
      continue;
    }
    const bool stream = out.is_stream_command();
    if (stream && has(kStructure, kind)) throw ForecastMismatch(fmt::format("{} in a job forecast without it", out.name));
    if (!live_in_job_) {
      expect_forecast(out);
      if (!stream || kind != K::start_of_job) continue;  // sent with the main program
      // The forecast had this job's marker and head just now: the job is jobs_[live_job_].
      const Job& job = jobs_[live_job_++];
      live_in_job_ = live_leading_ = true;
      live_tools_ = job.tools;
      cycle_ = job.first_cycle;
      live_in_cycle_ = false;
      queue_.emplace_back();
      bracket(queue_.back(), "@proc", *job.label, std::nullopt, job.index);
      add_tool_number(out, job);
      queue_.push_back(out);
      last_index_ = out.index;
      continue;
    }
    last_index_ = out.index;
    if (!stream) return true;
    if (live_tools_ > 0) {  // the job's opening tool changes were sent with its call
      --live_tools_;
      expect_forecast(out);
      continue;
    }
    if (std::exchange(live_leading_, false) && has(kToolChange, kind))
      throw ForecastMismatch(fmt::format("command #{} {}: more tool changes open the job than forecast", out.index, out.name));
    const Job& job = jobs_[live_job_ - 1];
    if (kind == K::drill) {
      live_cycle_ = Cycle{};
      live_cycle_.hash = kHashStart;
      live_in_cycle_ = true;
    } else if (live_in_cycle_ && kind == K::drill_point) {
      add_point(live_cycle_, out);
    } else if (live_in_cycle_ && kind == K::end_drill) {
      live_in_cycle_ = false;
      end_cycle(live_cycle_);
      if (cycle_ >= job.first_cycle + job.cycles || cycles_[cycle_].hash != live_cycle_.hash ||
          cycles_[cycle_].points != live_cycle_.points)
        throw ForecastMismatch("a drill cycle differs from the forecast");
      ++cycle_;
    } else if (kind == K::end_of_job) {
      live_in_job_ = false;
      if (cycle_ != job.first_cycle + job.cycles) throw ForecastMismatch("fewer drill cycles than the forecast");
      queue_.push_back(out);
      queue_.emplace_back();
      bracket(queue_.back(), "@end_proc", *job.label, true, last_index_);
      continue;
    }
    return true;
  }
}

// The next command of the forecast's main program (a job's marker and head included) must be `c`.
void ProcedureGeneration::expect_forecast(const toolpath::Command& c) {
  CommandKind kind;
  if (!main_->read(expected_, kind)) throw ForecastMismatch(fmt::format("{} after the end of the forecast", c.name));
  if (expected_.name == kJobMarker && !main_->read(expected_, kind))
    throw ForecastMismatch("a job's head missing from the forecast");
  if (!(expected_ == c))
    throw ForecastMismatch(fmt::format("command #{} {} where the forecast has #{} {}", c.index, c.name, expected_.index,
                                       expected_.name));
}

// The job has all come in: a job it ended inside ends there, and the main program's @end_of_file
// follows the bodies.
void ProcedureGeneration::end_live() {
  if (live_in_job_) {
    live_in_job_ = false;
    queue_.emplace_back();
    bracket(queue_.back(), "@end_proc", *jobs_[live_job_ - 1].label, true, last_index_);
  }
  toolpath::Command rest;
  if (live_job_ != jobs_.size() || main_->read(rest)) throw ForecastMismatch("the job ended before its forecast");
  bodies_sent_ = true;
  if (has_end_of_file_) {
    queue_.push_back(std::move(end_of_file_));
    has_end_of_file_ = false;
  }
}

bool ProcedureGeneration::next_points(toolpath::Command& out, CommandKind& kind) {
  for (;;) {
    if (pop_queue(out, kind)) return true;
    if (!bodies_->read(out, kind)) return false;
    last_index_ = out.index;
    if (out.is_stream_command() && kind == K::end_drill) {
      const std::int64_t label = *cycles_[shared_[next_proc_ - jobs_.size() - 1]].label;
      queue_.emplace_back();
      bracket(queue_.back(), "@end_proc", label, false, last_index_);
      if (!start_next_procedure()) phase_ = Phase::Main;
    }
    return true;
  }
}

}  // namespace prp
