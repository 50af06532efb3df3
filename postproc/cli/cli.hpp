// The `postproc` command line: one executable, one subcommand per job (read, run, check, ...).
#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace postproc::cli {

// Exit codes shared by every subcommand.
enum ExitCode : int { kOk = 0, kBadInput = 1, kUsage = 2 };

// A wrong command line: reported with the subcommand's usage, exit code 2.
struct UsageError {
  std::string message;
};

struct OptionSpec {
  std::string_view name;       // "--post"
  std::string_view short_name; // "-o" or empty
  bool takes_value = false;
  std::string_view help;
};

// The parsed command line of one subcommand.
class Arguments {
public:
  // Throws UsageError on an unknown option or a missing value.
  Arguments(std::span<const std::string> args, std::span<const OptionSpec> specs);

  bool has(std::string_view option) const { return values_.count(std::string(option)) > 0; }
  // The option's value (its last one when repeated), or `fallback` when the option was not given.
  std::string value(std::string_view option, std::string_view fallback = {}) const;
  // Every value of a repeatable option (--answer), in command-line order.
  std::vector<std::string> values(std::string_view option) const;
  const std::vector<std::string>& positional() const { return positional_; }

private:
  std::map<std::string, std::vector<std::string>, std::less<>> values_;
  std::vector<std::string> positional_;
};

struct Subcommand {
  std::string_view name;
  std::string_view usage;    // "postproc read [options] FILE"
  std::string_view summary;  // one line for `postproc --help`
  std::vector<OptionSpec> options;
  std::function<int(const Arguments&, std::ostream& out, std::ostream& err)> run;
};

// Every subcommand, in the order `postproc --help` lists them.
const std::vector<Subcommand>& subcommands();

// Entry point: dispatches `args` (without the program name) and returns the exit code.
int main(std::span<const std::string> args, std::ostream& out, std::ostream& err);

// The subcommands, one per file (cmd_*.cpp).
Subcommand read_command();
Subcommand run_command();
Subcommand check_command();
Subcommand test_command();
Subcommand explain_command();
Subcommand plot_command();
Subcommand verify_command();
Subcommand script_command();
Subcommand new_post_command();
Subcommand lsp_command();

}  // namespace postproc::cli
