// Subroutine generation on a flat toolpath (spec prp 3.0, 3.7; gpptool 2.3, 2.8): with
// `gen_procs = Y` every inline job (@start_of_job .. @end_of_job) becomes a procedure: the main
// program keeps the job's tool change and calls it with @call_proc, and the body follows the main
// program as @proc .. @end_proc, in label order, before @end_of_file. `drill_proc = Y` puts the
// point list that several drill cycles share into one procedure that each cycle calls.
// `gen_procs = C` makes a procedure only of a job that calls none (a job calling a shared point
// list stays inline; the point list stays a procedure).
//
// A toolpath that already has procedures or loops (a SolidCAM trace) passes unchanged: it is
// checked, never restructured (StructureCheck). Jobs are held in a temporary file, not in memory,
// because @start_of_file names the last procedure label and bodies follow the main program.
//
// Two passes, where the job and the PRP allow it (docs/prp.md, "Procedures in two passes"): a
// first pass over a skim of the job (forecast(): no basic motions inside jobs) finds the main
// program and the jobs' labels; the second pass (the constructor taking the forecast) sends that
// main program at once and then the bodies as the job streams in, each in its turn, instead of
// holding the whole job first. It checks everything outside the bodies against the forecast and
// throws ForecastMismatch where they differ: the run then starts again in one pass.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "prp/filters/command_spool.hpp"
#include "prp/filters/kind_source.hpp"
#include "prp/prp.hpp"

namespace prp {

class JobForecast;

class ProcedureGeneration final : public KindSource {
public:
  ProcedureGeneration(toolpath::CommandSource& input, const MachineParameters& params);
  // The second pass of two: `input` is the whole job, through the same filters as the forecast's.
  ProcedureGeneration(toolpath::CommandSource& input, const MachineParameters& params, JobForecast&& forecast);
  bool next_with_kind(toolpath::Command& out, CommandKind& kind) override;

  // True when the parameters ask for procedures (gen_procs Y or C).
  static bool needed(const MachineParameters& params);
  // The first pass of two, over `skimmed` (the job through the filters before this one, its basic
  // motions inside jobs left out): the main program and the jobs, or nothing when the job needs
  // one pass (a point list that drill cycles share, a job that stays inline, commands after
  // @end_of_file, a job already structured). Throws what the filters throw.
  static std::optional<JobForecast> forecast(toolpath::CommandSource& skimmed, const MachineParameters& params);

private:
  struct Job {
    std::int64_t offset = 0;  // of its @start_of_job in the body spool
    std::int64_t end = 0;     // just past its last command
    std::size_t index = 0;    // of its @start_of_job in the stream, for messages
    int tools = 0;            // tool-change commands right after @start_of_job (they stay in main)
    std::size_t first_cycle = 0, cycles = 0;
    std::optional<std::int64_t> label;  // when it becomes a procedure
    std::optional<toolpath::Value> tool_number;  // its first tool change's, else the one in the spindle
  };
  struct Cycle {
    std::uint64_t hash = 0;
    std::size_t index = 0;  // of its @drill in the stream, for messages
    std::size_t points = 0;
    std::int64_t points_offset = 0;  // first @drill_point in the body spool
    std::optional<std::int64_t> label;  // of the shared point list it calls
  };
  // PassThrough hands on what collect() read, then Through the rest of a structured toolpath.
  enum class Phase { Collect, PassThrough, Through, Main, Body, Points, Live, Done };
  friend class JobForecast;

  // Each of these hands out a command and its kind: the spools keep the kinds of the commands they
  // hold, so a replayed command's name is not classified again.
  bool produce(toolpath::Command& out, CommandKind& kind);
  // Reads the whole input; false when it is structured (pass through). A forecast keeps no bodies:
  // each job's head (its @start_of_job and opening tool changes) follows its marker in main_.
  bool collect();
  void assign_labels();
  bool next_main(toolpath::Command& out, CommandKind& kind);
  bool next_body(toolpath::Command& out, CommandKind& kind);
  bool next_points(toolpath::Command& out, CommandKind& kind);
  void queue_call(CommandSpool& head, const Job& job);
  bool go_live(toolpath::Command& out, CommandKind& kind);
  bool next_live(toolpath::Command& out, CommandKind& kind);
  void expect_forecast(const toolpath::Command& c);  // the next command of main_, or ForecastMismatch
  void end_live();
  bool pop_queue(toolpath::Command& out, CommandKind& kind);  // false when the queue is empty
  bool start_next_procedure();
  void call(toolpath::Command& out, std::int64_t label, const toolpath::Command* job);
  void bracket(toolpath::Command& out, const char* name, std::int64_t label, std::optional<bool> end_of_job,
               std::size_t index);

  KindedInput input_;
  std::string mode_;  // Y or C
  bool drill_proc_;
  NumberRange range_;
  std::int64_t first_label_;
  Phase phase_ = Phase::Collect;
  std::optional<CommandSpool> main_, bodies_;
  std::vector<Job> jobs_;
  std::vector<Cycle> cycles_;
  std::vector<std::size_t> shared_;  // cycles that own a shared point list, in label order
  std::set<std::int64_t> geometry_labels_;  // labels of the stream's turning geometry: not for jobs
  std::int64_t last_label_ = 0;
  std::deque<toolpath::Command> queue_;  // a handful of commands to hand out first
  toolpath::Command held_;               // a command read ahead in the pass-through phase
  bool has_held_ = false;
  // Body and point-list replay.
  bool body_inline_ = false;        // a body replayed inside the main program
  std::size_t body_job_ = 0, cycle_ = 0;
  int skip_tools_ = 0;              // tool changes of a procedure's job, sent in the main program
  std::size_t last_index_ = 0;      // of the last body command read
  bool skipping_points_ = false;    // after a @drill whose points are a shared procedure
  std::size_t next_proc_ = 0;       // next job (then shared list) whose body to send
  bool bodies_sent_ = false;
  toolpath::Command end_of_file_;
  bool has_end_of_file_ = false;
  // Two passes: forecasting_ in the first; in the second, the bodies stream in (Phase::Live).
  bool forecasting_ = false;
  bool forecast_ = false;
  bool live_in_job_ = false;
  bool live_leading_ = false;   // no body command of the job yet
  std::size_t live_job_ = 0;    // jobs whose body has started
  int live_tools_ = 0;          // opening tool changes of the job still to check
  Cycle live_cycle_;
  bool live_in_cycle_ = false;
  toolpath::Command expected_;  // scratch for expect_forecast
};

// What the first pass found (ProcedureGeneration::forecast); handed to the second pass.
class JobForecast {
private:
  friend class ProcedureGeneration;
  std::optional<CommandSpool> main;
  std::vector<ProcedureGeneration::Job> jobs;
  std::vector<ProcedureGeneration::Cycle> cycles;
  std::int64_t last_label = 0;
};

}  // namespace prp
