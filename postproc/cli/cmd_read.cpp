// `postproc read FILE`: reads a command stream (a `.trace`, or NC code of a modelled controller)
// and prints it in the canonical trace form.
#include <fmt/format.h>

#include <map>
#include <memory>
#include <ostream>

#include "machines/2xaxiscnc/reader.hpp"
#include "machines/pikocnc/reader.hpp"
#include "postproc/cli/cli.hpp"
#include "postproc/cli/open_input.hpp"
#include "postproc/engine/parameter_check.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_writer.hpp"

namespace postproc::cli {

namespace {

// A 2XAxisCNC program: every diagnostic is printed when the stream ends; errors (the frames were
// skipped or clamped) then fail the command with the first error's position.
std::unique_ptr<toolpath::CommandSource> open_twoaxis(const std::string& path, std::ostream& warnings) {
  struct Reporting final : toolpath::CommandSource {
    std::unique_ptr<twoaxis::TwoAxisReader> reader;
    std::ostream& warnings;
    Reporting(std::unique_ptr<twoaxis::TwoAxisReader> r, std::ostream& w) : reader(std::move(r)), warnings(w) {}
    bool next(toolpath::Command& out) override {
      if (reader->next(out)) return true;
      const twoaxis::Diagnostic* first_error = nullptr;
      for (const auto& d : reader->diagnostics()) {
        const bool error = d.severity == twoaxis::Diagnostic::Severity::Error;
        if (error && !first_error) first_error = &d;
        warnings << fmt::format("{}:{}:{}: {}: {}\n", d.file.empty() ? reader->file_name() : d.file, d.line, d.column,
                                error ? "error" : "warning", d.message);
      }
      const std::size_t hidden = reader->diagnostic_count() - reader->diagnostics().size();
      if (hidden > 0) warnings << fmt::format("{}: {} more diagnostics not shown\n", reader->file_name(), hidden);
      if (reader->error_count() > 0) {
        const auto& e = first_error ? *first_error : reader->diagnostics().front();
        throw toolpath::InputError({e.file.empty() ? reader->file_name() : e.file, e.line, e.column},
                                   fmt::format("{} error(s) in the program; the first: {}", reader->error_count(), e.message));
      }
      return false;
    }
  };
  return std::make_unique<Reporting>(twoaxis::TwoAxisReader::open(path), warnings);
}

}  // namespace

std::unique_ptr<toolpath::CommandSource> open_source(const std::string& path, const std::string& dialect,
                                                     std::ostream& warnings, bool nc_lines) {
  if (dialect == "trace") {
    struct Checked final : toolpath::CommandSource {  // catalogue types checked where they are read
      std::unique_ptr<toolpath::TraceReader> reader;
      postproc::ParameterCheck check;
      Checked(std::unique_ptr<toolpath::TraceReader> r, const std::string& name, std::ostream& warnings)
          : reader(std::move(r)), check(*reader, name, [&warnings](const toolpath::SourcePosition& at, const std::string& m) {
              warnings << fmt::format("{}:{}:{}: warning: {}\n", at.file, at.line, at.column, m);
            }) {}
      bool next(toolpath::Command& out) override { return check.next(out); }
    };
    return std::make_unique<Checked>(toolpath::TraceReader::open(path), path, warnings);
  }
  if (dialect == "2xaxiscnc") return open_twoaxis(path, warnings);
  const auto piko = pikocnc::parse_dialect(dialect);
  if (!piko)
    throw UsageError{"unknown dialect `" + dialect + "` (known: trace, pikocnc, pikocnc-2016, pikocnc-2025, 2xaxiscnc)"};
  pikocnc::Options options;
  options.dialect = *piko;
  options.nc_lines_in_trace = nc_lines;
  struct Reporting final : toolpath::CommandSource {
    std::unique_ptr<pikocnc::PikoReader> reader;
    std::ostream& warnings;
    Reporting(std::unique_ptr<pikocnc::PikoReader> r, std::ostream& w) : reader(std::move(r)), warnings(w) {}
    bool next(toolpath::Command& out) override {
      if (reader->next(out)) return true;
      const auto& d = reader->diagnostics();
      for (const auto& x : d.kept())
        warnings << fmt::format("{}:{}:{}: warning: {}\n", reader->file_name(), x.line, x.column, x.message);
      if (d.total() > d.kept().size())
        warnings << fmt::format("{}: {} more warnings not shown\n", reader->file_name(), d.total() - d.kept().size());
      return false;
    }
  };
  return std::make_unique<Reporting>(pikocnc::PikoReader::open(path, options), warnings);
}

namespace {

int run_read(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one input file"};
  auto reader = open_source(args.positional()[0], args.value("--dialect", "trace"), err, args.has("--nc-lines"));
  toolpath::Command command;
  if (args.has("--summary")) {
    std::map<std::string, std::size_t> counts;
    std::size_t total = 0, stream = 0;
    while (reader->next(command)) {
      ++counts[command.name];
      ++total;
      stream += command.is_stream_command();
    }
    out << fmt::format("{}: {} commands ({} stream commands)\n", args.positional()[0], total, stream);
    for (const auto& [name, n] : counts) out << fmt::format("  {:<24}{:>8}\n", name, n);
    return kOk;
  }
  toolpath::TraceWriter writer(out);
  while (reader->next(command)) writer.write(command);
  writer.flush();
  return kOk;
}

}  // namespace

Subcommand read_command() {
  return {
      "read",
      "postproc read [--dialect NAME] [--summary] FILE",
      "Read a command stream (or NC code) and print it in canonical trace form.",
      {
          {"--dialect", "", true, "input format: trace (default), pikocnc (= pikocnc-2025), pikocnc-2016, 2xaxiscnc"},
          {"--summary", "", false, "print the number of commands of each kind instead"},
          {"--nc-lines", "", false, "G-code input: attach each NC line to the first command it produced"},
      },
      run_read,
  };
}

}  // namespace postproc::cli
