#include "postproc/cli_support.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <iostream>

namespace postproc::cli {

std::vector<OptionSpec> engine_option_specs() {
  return {
      {"--post", "", true, "the GPP post (.gpp), required"},
      {"--prp", "", true, "the machine file: a PRP (.prp, the older .mac) or a VMID (.vmid, recognised by content)"},
      {"--include", "-I", true, "a folder where `inc` files are looked up"},
      {"--units", "", true, "metric or inch: which half of the PRP's pairs applies (default: the job's inch_system)"},
      {"--no-modal-reset", "", false, "keep modal memory across subroutine boundaries"},
  };
}

EngineOptions engine_options(const Arguments& args) {
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
  return o;
}

void print_machine_warnings(const Engine& engine, std::ostream& err) {
  for (const auto& w : engine.machine(prp::Units::Metric).warnings()) err << w.text(true) << '\n';
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

RunOptions run_options(const Input& input) {
  RunOptions o;
  o.input_name = input.path;
  std::string path = input.path;
  o.reopen = [path]() -> std::unique_ptr<toolpath::CommandSource> { return toolpath::TraceReader::open(path); };
  return o;
}

Progress::Progress(std::ostream& err, bool quiet, const Input& input)
    : err_(err), input_(input), enabled_(!quiet && &err == &std::cerr && ::isatty(STDERR_FILENO) != 0) {}

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

}  // namespace postproc::cli
