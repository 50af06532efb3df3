#include "tests/fuzz/entries.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "gppl/builtins/display_format.hpp"
#include "gppl/gppl.hpp"
#include "machines/2xaxiscnc/reader.hpp"
#include "machines/iso/reader.hpp"
#include "machines/ncmodel/tool_table.hpp"
#include "machines/pikocnc/model/reader.hpp"
#include "lsp/server.hpp"
#include "machines/registry/registry.hpp"
#include "machines/sinumerik/reader.hpp"
#include "machines/pikocnc/script/script.hpp"
#include "postproc/engine/engine.hpp"
#include "postproc/engine/parameter_check.hpp"
#include "prp/prp.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_writer.hpp"

namespace fuzz {
namespace {

// A stream buffer that throws everything away (output the entries do not look at).
struct Discard final : std::streambuf {
  int overflow(int c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// A broken promise of the code (not of the input): a finding.
[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz: %s\n", what);
  std::abort();
}

std::vector<toolpath::Command> read_all(const std::string& text) {
  std::istringstream in(text);
  toolpath::TraceReader reader(in, "fuzz.trace");
  postproc::ParameterCheck check(reader, "fuzz.trace");
  std::vector<toolpath::Command> all;
  toolpath::Command c;
  while (check.next(c)) all.push_back(c);
  return all;
}

// The trace format has no escapes: a string holding a quote or a line end cannot be written so that
// it reads back (docs/reliability.md); the round trip is held only for the others.
bool representable(const toolpath::Command& c) {
  for (const auto& p : c.parameters)
    if (p.value.kind == toolpath::ValueKind::String && p.value.text.find_first_of("'\"\r\n") != std::string::npos) return false;
  return true;
}

// A job of a few commands of every common kind: what a fuzzed post runs on.
constexpr std::string_view kJob = R"(@start_of_file
program_number : 1000
g_file_name : 'FUZZ'
@start_program
@change_tool
tool_number : 3
tool_diameter : 10.0
first_tool : TRUE
spin : 4000
@rapid_move
xpos : 5.0
ypos : -5.0
zpos : 10.0
@line
xpos : 5.0
ypos : 0.0
zpos : -2.0
feed : 400.0
@arc
xpos : 10.0
ypos : 5.0
zpos : -2.0
xcenter : 10.0
ycenter : 0.0
radius : 5.0
arc_direction : CCW
arc_plane : XY
feed : 400.0
@end_program
@end_of_file
)";

}  // namespace

// The skim of a first pass (TraceReader::skim_job_motions) gives the full read's commands, each
// as the full read gives it, leaving out only deeper commands and basic motions.
void check_skim(const std::string& text) {
  auto read = [&](bool skim) {
    std::istringstream in(text);
    toolpath::TraceReader reader(in, "fuzz.trace");
    if (skim) reader.skim_job_motions();
    std::vector<toolpath::Command> all;
    toolpath::Command c;
    while (reader.next(c)) all.push_back(c);
    return all;
  };
  std::vector<toolpath::Command> full, skimmed;
  try {
    full = read(false);
  } catch (const toolpath::InputError&) {
    return;
  }
  try {
    skimmed = read(true);
  } catch (const toolpath::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    broken("the skim fails where the full read does not");
  }
  std::size_t at = 0;
  auto left_out_until = [&](std::size_t index) {
    for (; at < full.size() && full[at].index != index; ++at) {
      const std::string_view n = full[at].name;
      const bool motion = toolpath::iequals(n, "@line") || toolpath::iequals(n, "@arc") || toolpath::iequals(n, "@rapid_move");
      if (full[at].is_stream_command() && !motion) broken("the skim left out a command it must keep");
    }
  };
  for (const toolpath::Command& c : skimmed) {
    left_out_until(c.index);
    if (at == full.size() || !(full[at] == c) || full[at].line != c.line) broken("the skim read a command otherwise");
    ++at;
  }
  left_out_until(static_cast<std::size_t>(-1));
}

// The fast path (the common lines straight from the chunk, numbers remembered per key) reads
// what the general rule reads: the same commands, positions and error.
void check_fast_path(const std::string& text) {
  auto read = [&](bool general, std::string& error) {
    std::istringstream in(text);
    toolpath::TraceReader reader(in, "fuzz.trace");
    if (general) reader.read_by_general_rule();
    std::vector<toolpath::Command> all;
    toolpath::Command a, b;  // two buffers in turn, so that the parameter shelf swaps them
    toolpath::Command* c = &a;
    try {
      while (reader.next(*c)) {
        all.push_back(*c);
        c = c == &a ? &b : &a;
      }
    } catch (const toolpath::InputError& e) {
      error = e.what();
    }
    return all;
  };
  std::string fast_error, general_error;
  const std::vector<toolpath::Command> fast = read(false, fast_error), general = read(true, general_error);
  if (fast_error != general_error) broken("the fast path fails otherwise than the general rule");
  if (fast.size() != general.size()) broken("the fast path reads another number of commands");
  for (std::size_t i = 0; i < fast.size(); ++i) {
    if (!(fast[i] == general[i]) || fast[i].line != general[i].line) broken("the fast path reads a command otherwise");
    for (std::size_t k = 0; k < fast[i].parameters.size(); ++k)
      if (fast[i].parameters[k].line != general[i].parameters[k].line ||
          fast[i].parameters[k].column != general[i].parameters[k].column)
        broken("the fast path puts a value elsewhere");
  }
}

void trace_reader(std::string_view data) {
  const std::string text(data);
  check_skim(text);
  check_fast_path(text);
  std::vector<toolpath::Command> first;
  try {
    first = read_all(text);
  } catch (const toolpath::InputError&) {
    return;
  }
  std::ostringstream out;
  {
    toolpath::TraceWriter writer(out);
    for (const auto& c : first) writer.write(c);
  }
  std::vector<toolpath::Command> again;
  try {
    again = read_all(out.str());
  } catch (const toolpath::InputError& e) {
    for (const auto& c : first)
      if (!representable(c)) return;  // the format has no escapes: such text cannot be written back
    std::fprintf(stderr, "%s\n", e.what());
    broken("the canonical form does not read back");
  }
  if (again.size() != first.size()) broken("the canonical form reads back another number of commands");
  for (std::size_t i = 0; i < first.size(); ++i)
    if (representable(first[i]) &&
        !(again[i].name == first[i].name && again[i].depth == first[i].depth && again[i].parameters == first[i].parameters))
      broken("the canonical form reads back other commands");
}

// As a run compiles a post, and as `postproc check` does (every name declared, constant
// assignments checked where they stand, "did you mean" hints).
void gppl_check(std::string_view data) {
  gppl::CompileOptions check;
  check.implicit_host_variables = false;
  check.check_constant_assignments = true;
  for (const gppl::CompileOptions& options : {gppl::CompileOptions{}, check}) {
    try {
      gppl::compile_source(data, "fuzz.gpp", options);
    } catch (const gppl::Error&) {
    } catch (const gppl::Errors&) {
    }
  }
}

void gppl_run(std::string_view data) {
  namespace fs = std::filesystem;
  static const fs::path dir = fs::temp_directory_path() / ("postproc-fuzz-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  struct Cleanup {  // nothing left in the temporary folder, whatever the input did
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{dir};
  std::ofstream(dir / "fuzz.gpp", std::ios::binary) << data;
  try {
    postproc::EngineOptions options;
    options.post = (dir / "fuzz.gpp").string();
    options.max_loop_iterations = 10000;  // bounded: a fuzzed `while` must not hang the target
    options.max_call_depth = 50;
    postproc::Engine engine(options);
    std::istringstream in{std::string(kJob)};
    toolpath::TraceReader reader(in, "fuzz.trace");
    postproc::OutputFiles files(dir, postproc::OutputFiles::LineEnd::LF, true);
    postproc::RunOptions run;
    run.input_name = "fuzz.trace";
    engine.run(reader, files, run);
    std::ostringstream nc;
    files.commit_to(nc);
  } catch (const toolpath::InputError&) {
  } catch (const gppl::Error&) {
  } catch (const gppl::Errors&) {
  } catch (const postproc::RunError&) {
  } catch (const prp::StreamError&) {
  }
}

void display_format(std::string_view data) {
  const std::size_t nl = data.find('\n');
  const std::string_view spec = data.substr(0, nl);
  gppl::DisplayFormat format;
  try {
    format = gppl::parse_display_format(spec);
  } catch (const gppl::Error&) {
    return;
  }
  for (double x : {0.0, -0.5, 1.25, 2.675, -123456.789, 1e15, 1e99, 1e101, 5e-324}) {
    try {
      (void)gppl::format_value(format, gppl::Value::of_numeric(x));
    } catch (const gppl::Error&) {
    }
  }
  for (std::int64_t i : {std::int64_t{0}, std::int64_t{-7}, std::int64_t{999999999}}) {
    try {
      (void)gppl::format_value(format, gppl::Value::of_integer(i));
    } catch (const gppl::Error&) {
    }
  }
}

void prp_loader(std::string_view data) {
  for (prp::Units units : {prp::Units::Metric, prp::Units::Inch}) {
    std::string written;
    try {
      written = prp::write_source(prp::load_source(data, "fuzz.prp", units));
    } catch (const prp::LoadError&) {
      continue;
    } catch (const toolpath::InputError&) {
      continue;
    }
    try {
      (void)prp::load_source(written, "written.prp", units);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      broken("the written PRP does not load");
    }
  }
}

// The loader picks the VMID reader by content (a first non-blank `<`): the input always gets one,
// so mutations explore the XML mapping rather than falling back to the PRP syntax.
void vmid(std::string_view data) {
  std::string xml;
  if (data.find_first_not_of(" \t\r\n") == std::string_view::npos || data[data.find_first_not_of(" \t\r\n")] != '<')
    xml = "<";
  xml += data;
  prp_loader(xml);
}

void twoaxis(std::string_view data) {
  // Never throws on a bad program (diagnostics instead); scripts are not looked up (no folder).
  auto reader = twoaxis::TwoAxisReader::from_string(std::string(data), "fuzz.nc");
  toolpath::Command c;
  long commands = 0;
  while (reader->next(c))
    if (++commands > 1'000'000) broken("a 2XAxisCNC program of bounded size gave more than a million commands");
}

void sinumerik(std::string_view data) {
  // Never throws on a bad block (diagnostics instead); no folder, so subprogram calls are errors. A
  // GOTOB loop is bounded by the executed-block limit, kept low here.
  sinumerik::Options options;
  options.max_executed_blocks = 5'000;
  auto reader = sinumerik::SinumerikReader::from_string(std::string(data), "fuzz.mpf", options);
  toolpath::Command c;
  long commands = 0;
  while (reader->next(c))
    if (++commands > 5'000'000) broken("a Sinumerik program of bounded size gave more than five million commands");
}

void iso(std::string_view data) {
  // The first byte picks the dialect (Fanuc, LinuxCNC, Mach3, GRBL) and whether a tool table
  // applies G43 H; never throws on a bad block. Loops (WHILE, repeat, M98 L) are bounded by the
  // executed-block limit, kept low here.
  static constexpr std::string_view kDialects[] = {"fanuc", "linuxcnc", "mach3", "grbl"};
  static const auto kTools = std::make_shared<const ncmodel::ToolTable>(
      ncmodel::parse_tool_table("T1 Z100\nT2 Z80.5 D6\nT3 Z-20\n", "fuzz.tbl"));
  const unsigned first = data.empty() ? 0u : static_cast<unsigned char>(data[0]);
  const iso::Rules& rules = *iso::rules_of(kDialects[first % 4]);
  iso::Options options;
  if (first & 4) options.tools = kTools;
  options.max_executed_blocks = 5'000;
  auto reader = iso::IsoReader::from_string(std::string(data), "fuzz.nc", rules, options);
  toolpath::Command c;
  long commands = 0;
  while (reader->next(c))
    if (++commands > 5'000'000) broken("an ISO program of bounded size gave more than five million commands");
}

void controllers(std::string_view data) {
  // Byte 1 picks a controller of the registry, byte 2 one of its names (a dialect variant) and how
  // it reads (for verify, NC lines); the rest is the program, read to its end with few blocks
  // executed. An error in the program is an InputError when the stream ends: no finding.
  if (data.size() < 2) return;
  const auto all = machines::controllers();
  const machines::Controller& controller = *all[static_cast<unsigned char>(data[0]) % all.size()];
  const unsigned how = static_cast<unsigned char>(data[1]);
  machines::ReadOptions options;
  options.max_blocks = 5'000;
  options.for_verify = (how & 0x80) != 0;
  options.nc_lines_in_trace = (how & 0x40) != 0;
  const auto names = controller.names();
  std::ostringstream warnings;
  try {
    auto source = controller.open_text(std::string(data.substr(2)), "fuzz.nc", names[(how & 0x3f) % names.size()],
                                       options, warnings);
    toolpath::Command c;
    long commands = 0;
    while (source->next(c))
      if (++commands > 5'000'000) broken("a program of bounded size gave more than five million commands");
  } catch (const toolpath::InputError&) {
  }
}

void tool_table(std::string_view data) {
  // A malformed line is an InputError naming it; anything else escaping is a finding.
  try {
    const ncmodel::ToolTable table = ncmodel::parse_tool_table(data, "fuzz.tbl");
    for (const auto& [number, t] : table.tools)
      if (number < 0 || !(t.diameter >= 0)) broken("a tool table kept a negative tool number or diameter");
  } catch (const toolpath::InputError&) {
  }
}

void lsp(std::string_view data) {
  // The bytes are what an editor sends on the server's standard input: frames, headers, JSON.
  // Every request gets an answer or an error; nothing the client sends may escape as an exception.
  Discard discard;
  std::ostream nowhere(&discard);
  std::istringstream in{std::string(data)};
  lsp::serve(in, nowhere, nowhere);
}

void pikocnc_script(std::string_view data) {
  // The G-code goes nowhere: a script may write a lot within its step budget.
  Discard discard;
  std::ostream nowhere(&discard);
  pikocnc::script::RunInputs inputs;
  inputs.max_steps = 20000;  // bounded: loops and recursion stop with an error, never hang
  inputs.max_call_depth = 50;
  inputs.default_answer = true;
  try {
    (void)pikocnc::script::run_script_text(data, "fuzz.pas", inputs, nowhere, nowhere);
  } catch (const toolpath::InputError&) {
  }
}

void pikocnc(std::string_view data) {
  pikocnc::Options options;
  options.dialect = !data.empty() && data.front() == ';' ? pikocnc::Dialect::V2016 : pikocnc::Dialect::V2025;
  options.max_executed_lines = 20000;  // bounded: loops and cycles stop with an error, never hang
  options.max_commands = 20000;
  options.m99_restarts = 2;
  std::istringstream in{std::string(data)};
  pikocnc::PikoReader reader(in, "fuzz.nc", options);
  toolpath::Command c;
  try {
    while (reader.next(c)) {
    }
  } catch (const toolpath::InputError&) {
  }
}

Entry entry(std::string_view target) {
  struct Named {
    std::string_view name;
    Entry entry;
  };
  static constexpr Named kEntries[] = {
      {"trace_reader", trace_reader}, {"gppl_check", gppl_check}, {"gppl_run", gppl_run},
      {"display_format", display_format}, {"prp_loader", prp_loader}, {"pikocnc", pikocnc},
      {"vmid", vmid}, {"twoaxis", twoaxis}, {"pikocnc_script", pikocnc_script}, {"sinumerik", sinumerik},
      {"iso", iso}, {"controllers", controllers}, {"lsp", lsp}, {"tool_table", tool_table},
  };
  for (const Named& n : kEntries)
    if (n.name == target) return n.entry;
  return nullptr;
}

}  // namespace fuzz
