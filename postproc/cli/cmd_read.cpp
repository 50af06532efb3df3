// `postproc read FILE`: reads a command stream (a `.trace`, or NC code of a modelled controller)
// and prints it in the canonical trace form.
#include <fmt/format.h>

#include <map>
#include <memory>
#include <ostream>

#include "machines/registry/registry.hpp"
#include "postproc/cli/cli.hpp"
#include "postproc/cli/open_input.hpp"
#include "postproc/engine/parameter_check.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_writer.hpp"

namespace postproc::cli {

std::unique_ptr<toolpath::CommandSource> open_source(const std::string& path, const std::string& dialect,
                                                     std::ostream& warnings, const machines::ReadOptions& options) {
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
  const machines::Controller* controller = machines::find_controller(dialect);
  if (!controller)
    throw UsageError{"unknown dialect `" + dialect + "` (known: trace, " + machines::controller_names() + ")"};
  return controller->open(path, dialect, options, warnings);
}

machines::ReadOptions read_options(const Arguments& args) {
  machines::ReadOptions options;
  options.nc_lines_in_trace = args.has("--nc-lines");
  if (args.has("--tool-table")) options.tool_table = args.value("--tool-table");
  return options;
}

std::string dialect_help(std::string_view what) {
  return fmt::format("{}: trace, {}", what, machines::controller_names());
}

std::string_view input_help() {
  static const std::string help = dialect_help("input format (default trace)");
  return help;
}

namespace {

int run_read(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one input file"};
  auto reader = open_source(args.positional()[0], args.value("--dialect", "trace"), err, read_options(args));
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
  toolpath::write_trace(*reader, out);
  return kOk;
}

}  // namespace

Subcommand read_command() {
  return {
      "read",
      "postproc read [--dialect NAME] [--summary] FILE",
      "Read a command stream (or NC code) and print it in canonical trace form.",
      {
          {"--dialect", "", true, input_help()},
          {"--summary", "", false, "print the number of commands of each kind instead"},
          {"--nc-lines", "", false, "G-code input: attach each NC line to the first command it produced"},
          kToolTableOption,
      },
      run_read,
  };
}

}  // namespace postproc::cli
