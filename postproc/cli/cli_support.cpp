#include "postproc/cli/cli_support.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>

#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"

namespace postproc::cli {

std::vector<OptionSpec> engine_option_specs() {
  return {
      {"--post", "", true, "the GPP post (.gpp), required"},
      {"--prp", "", true, "the machine file: a PRP (.prp, the older .mac) or a VMID (.vmid, recognised by content)"},
      {"--include", "-I", true, "a folder where `inc` files are looked up"},
      {"--units", "", true, "metric or inch: which half of the PRP's pairs applies (default: the job's inch_system)"},
      {"--no-modal-reset", "", false, "keep modal memory across subroutine boundaries"},
      {"--answer", "", true, "NAME=VALUE: the answer to the post's `input` of NAME (repeatable)"},
      {"--answers", "", true, "a file of NAME=VALUE lines (`#` comments) answering `input` statements"},
      {"--progress", "", false, "draw the progress bar even when stderr is not a terminal (a log of a long run)"},
      {"--trace", "", true, "LEVEL[:FILE]: trace the post as SolidCAM does (LEVEL 0-5 for every procedure, "
                            "`post` for the post's own trace statements), to stderr or FILE"},
  };
}

namespace {

constexpr std::size_t kMaxAnswerLine = std::size_t{1} << 20;

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::vector<gppl::Answer> read_answers_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the answers file");
  std::vector<gppl::Answer> answers;
  std::string line;
  for (std::size_t number = 1;; ++number) {
    // Answers are short lines: a longer one (/dev/zero, a binary file) would only take memory.
    const toolpath::LineRead got = toolpath::read_line(in, line, kMaxAnswerLine);
    if (got == toolpath::LineRead::End) break;
    if (got == toolpath::LineRead::TooLong)
      throw std::runtime_error(fmt::format("{}:{}:1: line longer than 1 MiB: not an answers file?", path, number));
    const std::string_view text = trimmed(line);
    if (text.empty() || text.front() == '#') continue;
    const std::size_t eq = text.find('=');
    const std::string_view name = eq == std::string_view::npos ? std::string_view() : trimmed(text.substr(0, eq));
    if (name.empty()) {
      const std::size_t column = std::size_t(text.data() - line.data()) + 1;
      throw std::runtime_error(
          fmt::format("{}:{}:{}: expected NAME=VALUE (or a # comment), not `{}`", path, number, column, toolpath::excerpt(text)));
    }
    answers.push_back({std::string(name), std::string(trimmed(text.substr(eq + 1))), fmt::format("{}:{}", path, number)});
  }
  if (in.bad()) throw std::runtime_error(fmt::format("{}: read error: {}", path, std::strerror(errno)));
  return answers;
}

EngineOptions engine_options(const Arguments& args, std::ostream* log) {
  EngineOptions o;
  o.post = args.value("--post");
  if (o.post.empty()) throw UsageError{"--post is required"};
  o.prp = args.value("--prp");
  if (args.has("--include")) o.include_paths.push_back(args.value("--include"));
  if (args.has("--units")) {
    std::string units = args.value("--units");
    if (units == "inch")
      o.units = prp::Units::Inch;
    else if (units == "metric")
      o.units = prp::Units::Metric;
    else
      throw UsageError{"--units must be metric or inch, not `" + units + "`"};
  }
  o.reset_modal_memory_at_subroutines = !args.has("--no-modal-reset");
  // The file first, so that an --answer on the command line overrides it (the last answer wins).
  for (const std::string& file : args.values("--answers"))
    for (auto& a : read_answers_file(file)) o.answers.push_back(std::move(a));
  for (const std::string& given : args.values("--answer")) {
    const std::size_t eq = given.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError{"--answer needs NAME=VALUE, not `" + given + "`"};
    o.answers.push_back({given.substr(0, eq), given.substr(eq + 1), "--answer " + given});
  }
  o.log = log;
  o.log_inputs = !args.has("--quiet");
  return o;
}

void print_machine_warnings(const prp::MachineParameters& machine, std::ostream& err) {
  for (const auto& w : machine.warnings()) err << w.text() << '\n';
}

void print_machine_warnings(const Engine& engine, std::ostream& err) {
  print_machine_warnings(engine.machine(prp::Units::Metric), err);
}

Input Input::open(const std::string& path) {
  Input in;
  in.path = path;
  in.stream = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in.stream) throw toolpath::InputError({path, 0, 0}, "cannot open file");
  std::error_code ignored;
  in.size = std::filesystem::file_size(path, ignored);
  in.reader = std::make_unique<toolpath::TraceReader>(*in.stream, path);
  return in;
}

RunOptions run_options(const Input& input, std::ostream& warnings) {
  RunOptions o;
  o.input_name = input.path;
  o.warnings = &warnings;
  std::string path = input.path;
  o.reopen = [path]() -> std::unique_ptr<toolpath::CommandSource> { return toolpath::TraceReader::open(path); };
  return o;
}

TraceOutput::TraceOutput(const Arguments& args, std::ostream& err) {
  if (!args.has("--trace")) return;
  const std::string value = args.value("--trace");
  const std::size_t colon = value.find(':');
  const std::string level = value.substr(0, colon);
  if (level == "post") {
    level_ = -1;
  } else if (level.size() == 1 && level[0] >= '0' && level[0] <= '5') {
    level_ = level[0] - '0';
  } else {
    throw UsageError{"--trace takes LEVEL[:FILE], LEVEL 0 to 5 or `post`, not `" + value + "`"};
  }
  stream_ = &err;
  if (colon != std::string::npos) {
    const std::string path = value.substr(colon + 1);
    file_ = std::make_unique<std::ofstream>(path, std::ios::binary);
    if (!*file_) throw std::runtime_error(path + ": cannot write the trace");
    stream_ = file_.get();
  }
}

void TraceOutput::apply(RunOptions& options) {
  options.trace = stream_;
  options.trace_level = level_;
}

Progress::Progress(std::ostream& err, bool quiet, const Input& input, bool forced)
    : err_(err), input_(input), enabled_(forced || (!quiet && &err == &std::cerr && ::isatty(STDERR_FILENO) != 0)) {}

Progress::~Progress() {
  if (drawn_) err_ << "\r\033[K" << std::flush;  // leave the terminal as it was
}

void Progress::update(std::size_t commands) {
  if (!enabled_) return;
  auto now = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
                 .count();
  if (now - last_ms_ < 100) return;
  last_ms_ = now;
  double fraction = 0;
  if (input_.size > 0)  // the reader runs on a thread of its own: ask it, not the stream
    fraction = std::min(1.0, static_cast<double>(input_.reader->bytes_read()) / static_cast<double>(input_.size));
  constexpr int kWidth = 30;
  int filled = static_cast<int>(fraction * kWidth);
  err_ << fmt::format("\r[{}{}] {:3.0f}%  {} commands", std::string(static_cast<std::size_t>(filled), '#'),
                      std::string(static_cast<std::size_t>(kWidth - filled), ' '), fraction * 100, commands)
       << std::flush;
  drawn_ = true;
}

Destination Destination::parse(const std::string& o) {
  Destination d;
  if (o.empty() || o == "-") return d;
  d.to_stdout = false;
  std::filesystem::path p(o);
  if (std::filesystem::is_directory(p) || o.back() == '/') {
    d.directory = p;
    return d;
  }
  d.main_file = p;
  d.directory = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  return d;
}

void write_file_replacing(const std::string& path, std::string_view text) {
  const std::string temp = path + ".tmp";
  {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!file.flush()) {
      std::error_code ec;
      std::filesystem::remove(temp, ec);
      throw toolpath::InputError({path, 0, 0}, "cannot write file");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    throw toolpath::InputError({path, 0, 0}, "cannot write file");
  }
}

}  // namespace postproc::cli
