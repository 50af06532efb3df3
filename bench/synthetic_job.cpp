#include "bench/synthetic_job.hpp"

#include <cmath>
#include <fstream>
#include <span>
#include <stdexcept>

#include "toolpath/trace_writer.hpp"

namespace bench {
namespace {

using toolpath::Value;

double round3(double v) { return std::round(v * 1000.0) / 1000.0; }

// The commands around the motions, in the order of each shape.
enum class Frame {
  start_of_file, def_tool, machine_plane, start_program, start_of_job, change_tool,
  call_proc, end_program, proc, end_of_job, end_proc, end_of_file
};
using F = Frame;
constexpr Frame kFlatHead[] = {F::start_of_file, F::def_tool, F::machine_plane, F::start_program, F::start_of_job,
                               F::change_tool};
constexpr Frame kFlatTail[] = {F::end_of_job, F::end_program, F::end_of_file};
constexpr Frame kProcHead[] = {F::start_of_file, F::def_tool, F::machine_plane, F::start_program, F::change_tool,
                               F::call_proc,     F::end_program, F::proc,         F::start_of_job};
constexpr Frame kProcTail[] = {F::end_of_job, F::end_proc, F::end_of_file};

// The job's own parameters, which @call_proc repeats (gpptool 2.8) with the job's tool.
void job_parameters(toolpath::Command& c, bool with_tool) {
  c.set("job_name", Value::make_string("F-BENCH"));
  c.set("job_type", Value::make_string("profile"));
  if (with_tool) c.set("tool_number", Value::make_integer(4));
}

void frame(toolpath::Command& c, Frame f, JobShape shape) {
  const bool procedures = shape == JobShape::procedures;
  switch (f) {
    case F::start_of_file:
      c.name = "@start_of_file";
      c.set("program_number", Value::make_integer(1234));
      c.set("g_file_name", Value::make_string("BENCH"));
      c.set("first_proc_number", Value::make_integer(1));
      c.set("last_proc_number", Value::make_integer(1));
      c.set("first_user_proc", Value::make_integer(procedures ? 2 : 1));
      c.set("home_number", Value::make_integer(1));
      break;
    case F::def_tool:
      c.name = "@def_tool";
      c.set("tool_number", Value::make_integer(4));
      c.set("tool_offset", Value::make_numeric(5.0));
      break;
    case F::machine_plane:
      c.name = "@machine_plane";
      c.set("machine_plane", Value::make_enum("XY"));
      break;
    case F::start_program: c.name = "@start_program"; break;
    case F::start_of_job:
      c.name = "@start_of_job";
      job_parameters(c, procedures);
      break;
    case F::change_tool:
      c.name = "@change_tool";
      c.set("tool_number", Value::make_integer(4));
      c.set("tool_diameter", Value::make_numeric(10.0));
      c.set("xnext", Value::make_numeric(0.0));
      c.set("ynext", Value::make_numeric(0.0));
      c.set("znext", Value::make_numeric(50.0));
      c.set("spin", Value::make_integer(6000));
      break;
    case F::call_proc:
      c.name = "@call_proc";
      job_parameters(c, true);
      c.set("message", Value::make_string("F-BENCH"));
      c.set("label", Value::make_integer(1));
      c.set("proc_count", Value::make_integer(1));
      break;
    case F::end_program: c.name = "@end_program"; break;
    case F::proc:
      c.name = "@proc";
      c.set("label", Value::make_integer(1));
      break;
    case F::end_of_job: c.name = "@end_of_job"; break;
    case F::end_proc:
      c.name = "@end_proc";
      c.set("label", Value::make_integer(1));
      c.set("end_of_job", Value::make_logical(true));
      break;
    case F::end_of_file: c.name = "@end_of_file"; break;
  }
}

// Motion i of a contour made of 40-mm lines joined by 5-mm quarter arcs, stepping down 0.5 mm per lap.
void motion(toolpath::Command& c, std::size_t i) {
  const std::size_t lap = i / 8, k = i % 8;
  const double z = round3(-0.5 * static_cast<double>(lap % 40 + 1));
  const double feed = lap % 2 ? 1200.0 : 1500.0;
  const double corners[4][2] = {{45, 0}, {50, 45}, {5, 50}, {0, 5}};  // where each line ends
  const double centres[4][2] = {{45, 5}, {45, 45}, {5, 45}, {5, 5}};  // centre of the arc after it
  const double ends[4][2] = {{50, 5}, {45, 50}, {0, 45}, {5, 0}};     // where that arc ends
  const std::size_t side = k / 2;
  if (k % 2 == 0) {
    c.name = "@line";
    c.set("xpos", Value::make_numeric(corners[side][0]));
    c.set("ypos", Value::make_numeric(corners[side][1]));
    c.set("zpos", Value::make_numeric(z));
    c.set("feed", Value::make_numeric(feed));
    return;
  }
  c.name = "@arc";
  c.set("xpos", Value::make_numeric(ends[side][0]));
  c.set("ypos", Value::make_numeric(ends[side][1]));
  c.set("zpos", Value::make_numeric(z));
  c.set("feed", Value::make_numeric(feed));
  c.set("xcenter", Value::make_numeric(centres[side][0]));
  c.set("ycenter", Value::make_numeric(centres[side][1]));
  c.set("xcenter_rel", Value::make_numeric(round3(centres[side][0] - corners[side][0])));
  c.set("ycenter_rel", Value::make_numeric(round3(centres[side][1] - corners[side][1])));
  c.set("radius", Value::make_numeric(5.0));
  c.set("start_angle", Value::make_numeric(std::fmod(270.0 + 90.0 * static_cast<double>(side), 360.0)));
  c.set("end_angle", Value::make_numeric(std::fmod(360.0 + 90.0 * static_cast<double>(side), 360.0)));
  c.set("arc_direction", Value::make_enum("CCW"));
  c.set("arc_plane", Value::make_enum("XY"));
  c.set("arc_size", Value::make_numeric(90.0));
}

}  // namespace

bool SyntheticJob::next(toolpath::Command& out) {
  const bool procedures = shape_ == JobShape::procedures;
  const std::span<const Frame> head = procedures ? std::span<const Frame>(kProcHead) : std::span<const Frame>(kFlatHead);
  const std::span<const Frame> tail = procedures ? std::span<const Frame>(kProcTail) : std::span<const Frame>(kFlatTail);
  if (step_ >= head.size() + motions_ + tail.size()) return false;
  out.clear();
  out.depth = 1;
  out.index = index_++;
  if (step_ < head.size()) frame(out, head[step_], shape_);
  else if (step_ < head.size() + motions_) motion(out, step_ - head.size());
  else frame(out, tail[step_ - head.size() - motions_], shape_);
  ++step_;
  return true;
}

void write_job(std::ostream& out, std::size_t motions, JobShape shape) {
  SyntheticJob job(motions, shape);
  toolpath::TraceWriter writer(out);
  toolpath::Command c;
  while (job.next(c)) writer.write(c);
  writer.flush();
}

void write_job(const std::string& path, std::size_t motions, JobShape shape) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot write " + path);
  write_job(out, motions, shape);
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace bench
