// hand_post: the project's hand-written Fanuc post, the "ceiling" the engine is measured against
// (issue 25; bench/ceiling_bench.cpp runs both). It reads a SolidCAM-layout trace and writes the
// NC program that `postproc run --post machines/fanuc/fanuc.gpp --prp machines/fanuc/fanuc.prp`
// writes for it, byte for byte, with nothing general in between: no interpreter, no command
// objects, no filter chain. What the post and the PRP do is spelled out in C++ for the commands
// and parameters it meets.
//
// Scope: the jobs bench/make_job writes, in both shapes.
//   - procedures (SolidCAM with gen_procs = Y): @start_of_file, @def_tool, @machine_plane,
//     @start_program, @change_tool, @call_proc, @end_program, @proc, @start_of_job, @line, @arc,
//     @end_of_job, @end_proc, @end_of_file, posted in the order they come;
//   - flat (one inline job, @start_of_job .. @end_of_job): restructured as the PRP's gen_procs = Y
//     does (prp::ProcedureGeneration): the tool changes that open the job stay in the main program,
//     which calls the job (M98 P1) and ends (@end_program), and the job follows as O1 .. M99. The
//     main program's end is written where that restructured stream puts it, right after the call.
// The shipped fanuc.prp is built in: movement_precision 0.001 and zero_value 0.001 (the precision
// filter's zero snap, "an axis that barely moved keeps its value" and rounding half away from
// zero, computed as the engine computes them), gen_procs = Y with the first label 1
// (proc_num_dflt), no feed or spin precision; the PRP's arc and short-line filters change nothing
// on these jobs (an arc they would change is refused). The post's modal memory is reset at @proc
// and after @call_proc, as `postproc run` does by default.
//
// Anything else is refused (OutOfScope, naming the byte offset), never guessed: another command
// (@rapid_move, @drill, @compensation, loops...), a depth other than 1, a motion without all of
// xpos/ypos/zpos/feed, an arc the PRP might linearise or make a line of (radius above 2000 mm,
// sweep below 0.01 degree, length below 0.01 mm), xnext/ynext/znext with more than three
// decimals, a flat job with more than one job or with commands between @end_of_job and
// @end_program. The arcs' own values are trusted (the engine checks them against the tool
// position). On refusal no NC file is written.
//
// How it is fast: the trace is read in 1 MiB blocks (a block holds whole commands; the cut-off
// command moves to the front for the next read); name:value pairs are found with bit masks of 64
// bytes at a time (SSE2) and only the parameters the post prints are parsed; coordinates become
// integer thousandths straight from their decimal text (a double only where the engine's rule
// needs one); modal values are compared as integers; the digits go straight into a 1 MiB output
// buffer that write() empties. One thread.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace bench::hand_post {

struct Stats {
  std::uint64_t commands = 0;  // commands read
  std::uint64_t lines = 0;     // NC lines written
  std::uint64_t bytes = 0;     // NC bytes written
};

// A trace that is not a make_job job (see above), or one this post cannot read.
class OutOfScope : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// Posts the trace file `trace_path` into `nc_path` (written as nc_path + ".part", renamed when
// whole). Throws OutOfScope, or std::runtime_error for a file that cannot be read or written.
Stats post_file(const std::string& trace_path, const std::string& nc_path);

// The same post from text to text (tests).
std::string post_text(std::string_view trace, Stats* stats = nullptr);

}  // namespace bench::hand_post
