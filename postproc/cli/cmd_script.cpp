// `postproc script run|check FILE`: runs a PikoCNC script (machines/pikocnc/script/) without a user,
// taking the dialog's values, the answers and the constants from the command line and a
// parameters file (spec pikocnc-scripts section 10). The subcommand only parses and calls.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "machines/pikocnc/script/script.hpp"
#include "postproc/cli/cli.hpp"
#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"

namespace postproc::cli {

namespace {

namespace script = pikocnc::script;

// Scripts and their parameter files are kilobytes: a file past 16 MiB (/dev/zero, a wrong file)
// is an error rather than memory taken without bound.
std::string read_file(const std::string& path, std::string_view kind) {
  return toolpath::read_file_bounded(path, std::size_t{16} << 20, fmt::format("larger than 16 MiB: not {}?", kind),
                                     "cannot read file");
}

// NAME=VALUE from --arg / --const.
std::pair<std::string, std::string> split_pair(const std::string& text, const char* option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw UsageError{fmt::format("{} expects NAME=VALUE, got `{}`", option, text)};
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::uint64_t number_option(const Arguments& args, const char* option, std::uint64_t fallback) {
  if (!args.has(option)) return fallback;
  const std::string v = args.value(option);
  if (v.empty() || v.size() > 12 || v.find_first_not_of("0123456789") != std::string::npos)
    throw UsageError{fmt::format("{} expects a non-negative integer, got `{}`", option, v)};
  return std::stoull(v);
}

script::RunInputs inputs_from(const Arguments& args) {
  script::RunInputs in;
  for (const auto& a : args.values("--arg")) {
    auto [k, v] = split_pair(a, "--arg");
    in.args[k] = v;
  }
  for (const auto& c : args.values("--const")) {
    auto [k, v] = split_pair(c, "--const");
    in.constants[k] = v;
  }
  for (const auto& a : args.values("--answer")) {
    const auto answer = script::parse_answer(a);
    if (!answer) throw UsageError{fmt::format("--answer expects yes or no, got `{}`", a)};
    in.ordered_answers.push_back(*answer);
  }
  if (args.has("--params")) script::read_parameters(read_file(args.value("--params"), "a parameters file"), args.value("--params"), in);
  in.run_count = std::int32_t(number_option(args, "--run-count", 0) & 0x7fffffff);
  in.max_steps = number_option(args, "--max-steps", in.max_steps);
  in.describe_args = args.has("--describe-args");
  in.crlf = args.has("--crlf");
  return in;
}

int run_script(const Arguments& args, std::ostream& out, std::ostream& err) {
  const auto& pos = args.positional();
  if (pos.size() != 2 || (pos[0] != "run" && pos[0] != "check"))
    throw UsageError{"expected `run FILE` or `check FILE`"};
  const std::string& path = pos[1];
  const std::string text = read_file(path, "a PikoCNC script");
  const auto program = script::parse_script(text, path);
  if (pos[0] == "check") {
    out << fmt::format("{}: ok\n", path);
    return kOk;
  }
  const script::RunInputs in = inputs_from(args);
  const std::string output = args.value("--output");
  if (output.empty() || output == "-") {
    // stdout: held in memory so that a failing script prints no partial program (spec 2.6).
    std::ostringstream gcode;
    script::run_script(*program, in, gcode, err);
    out << gcode.str();
    return kOk;
  }
  // A file: streamed to a temporary name, renamed only when the run succeeds.
  const std::string temp = output + ".tmp";
  script::RunResult result;
  try {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) throw toolpath::InputError({output, 0, 0}, "cannot write file");
    result = script::run_script(*program, in, file, err);
    if (!file.flush()) throw toolpath::InputError({output, 0, 0}, "cannot write file");
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    throw;
  }
  std::error_code ec;
  std::filesystem::rename(temp, output, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    throw toolpath::InputError({output, 0, 0}, "cannot write file");
  }
  if (!result.described) err << fmt::format("{}: wrote {} ({} lines)\n", path, output, result.lines);
  return kOk;
}

}  // namespace

Subcommand script_command() {
  return {
      "script",
      "postproc script run|check FILE [--arg N=V]... [--const NAME=V]... [--answer yes|no]... [--params FILE] [-o OUT]",
      "Run a PikoCNC script (Pascal) that generates a G-code program, without a user.",
      {
          {"--output", "-o", true, "the G-code file to write (temporary name, renamed on success); stdout when absent"},
          {"--arg", "", true, "N=VALUE: the value of dialog argument N, checked against its widget (repeatable)"},
          {"--const", "", true, "NAME=VALUE: a predefined constant such as MAT_SIZE_X (repeatable)"},
          {"--answer", "", true, "yes|no: the next MsgYesNo answer, used in order (repeatable)"},
          {"--params", "", true, "a parameters file with [constants], [args] and [answers]; the command line wins"},
          {"--run-count", "", true, "RUN_CNT (default 0: the first run, which sets the argument defaults)"},
          {"--describe-args", "", false, "print the parameter dialog as JSON at ArgEdit and stop, without G-code"},
          {"--max-steps", "", true, "statements executed before the script is stopped as runaway (default 200000000)"},
          {"--crlf", "", false, "end the G-code lines with CR LF"},
      },
      run_script,
  };
}

}  // namespace postproc::cli
