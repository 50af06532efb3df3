// `postproc read FILE`: reads a command stream and prints it in the canonical trace form.
#include <fmt/format.h>

#include <map>
#include <ostream>

#include "postproc/cli.hpp"
#include "toolpath/trace_reader.hpp"
#include "toolpath/trace_writer.hpp"

namespace postproc::cli {
namespace {

int run_read(const Arguments& args, std::ostream& out, std::ostream&) {
  if (args.positional().size() != 1) throw UsageError{"expected one input file"};
  const std::string dialect = args.value("--dialect", "trace");
  if (dialect != "trace") throw UsageError{"unknown dialect `" + dialect + "` (known: trace)"};

  auto reader = toolpath::TraceReader::open(args.positional()[0]);
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
      "Read a command stream and print it in canonical trace form.",
      {
          {"--dialect", "", true, "input format: trace (default)"},
          {"--summary", "", false, "print the number of commands of each kind instead"},
      },
      run_read,
  };
}

}  // namespace postproc::cli
