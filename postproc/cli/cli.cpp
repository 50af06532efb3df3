#include "postproc/cli/cli.hpp"

#include <cerrno>
#include <cstring>
#include <exception>
#include <stdexcept>

#include "postproc/cli/version.hpp"

namespace postproc::cli {

Arguments::Arguments(std::span<const std::string> args, std::span<const OptionSpec> specs) {
  auto find = [&](std::string_view word) -> const OptionSpec* {
    for (const auto& s : specs)
      if (word == s.name || (!s.short_name.empty() && word == s.short_name)) return &s;
    return nullptr;
  };
  bool options_done = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (options_done || a.size() < 2 || a[0] != '-') {
      positional_.push_back(a);
      continue;
    }
    if (a == "--") {
      options_done = true;
      continue;
    }
    std::string word = a, inline_value;
    bool has_inline = false;
    if (auto eq = a.find('='); a.rfind("--", 0) == 0 && eq != std::string::npos) {
      word = a.substr(0, eq);
      inline_value = a.substr(eq + 1);
      has_inline = true;
    }
    const OptionSpec* spec = find(word);
    if (!spec) throw UsageError{"unknown option " + word};
    std::string key(spec->name);
    if (!spec->takes_value) {
      if (has_inline) throw UsageError{"option " + key + " takes no value"};
      values_[key].push_back("");
    } else if (has_inline) {
      values_[key].push_back(inline_value);
    } else {
      if (i + 1 >= args.size()) throw UsageError{"option " + key + " needs a value"};
      values_[key].push_back(args[++i]);
    }
  }
}

std::string Arguments::value(std::string_view option, std::string_view fallback) const {
  auto it = values_.find(option);
  return it == values_.end() ? std::string(fallback) : it->second.back();
}

std::vector<std::string> Arguments::values(std::string_view option) const {
  auto it = values_.find(option);
  return it == values_.end() ? std::vector<std::string>() : it->second;
}

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> all = {
      read_command(),
      run_command(),
      check_command(),
      test_command(),
      explain_command(),
      plot_command(),
      verify_command(),
      script_command(),
      new_post_command(),
      lsp_command(),
  };
  return all;
}

namespace {

const OptionSpec kHelp{"--help", "-h", false, "show this help and exit"};

void print_main_help(std::ostream& out) {
  out << "postproc " << kVersion << ": SolidCAM-style post-processor\n\n"
      << "usage: postproc <command> [options] ...\n\ncommands:\n";
  for (const auto& c : subcommands()) {
    std::string name(c.name);
    name.resize(10, ' ');
    out << "  " << name << c.summary << '\n';
  }
  out << "\n`postproc <command> --help` describes a command.\n"
      << "Exit codes: 0 ok, 1 error in the input, 2 wrong command line.\n";
}

void print_help(const Subcommand& c, std::ostream& out) {
  out << "usage: " << c.usage << "\n\n" << c.summary << "\n\noptions:\n";
  auto line = [&](const OptionSpec& o) {
    std::string left = std::string(o.short_name.empty() ? "    " : std::string(o.short_name) + ", ") + std::string(o.name);
    if (o.takes_value) left += " VALUE";
    left.resize(std::max<std::size_t>(left.size() + 2, 26), ' ');
    out << "  " << left << o.help << '\n';
  };
  for (const auto& o : c.options) line(o);
  line(kHelp);
}

}  // namespace

int main(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    print_main_help(err);
    return kUsage;
  }
  const std::string& first = args[0];
  if (first == "--help" || first == "-h" || first == "help") {
    print_main_help(out);
    return kOk;
  }
  if (first == "--version") {
    out << "postproc " << kVersion << '\n';
    return kOk;
  }
  for (const auto& c : subcommands()) {
    if (c.name != first) continue;
    std::vector<OptionSpec> specs = c.options;
    specs.push_back(kHelp);
    try {
      Arguments parsed(args.subspan(1), specs);
      if (parsed.has("--help")) {
        print_help(c, out);
        return kOk;
      }
      const int code = c.run(parsed, out, err);
      // Output that did not reach its place (stdout on a full disk) is a failed run, not a success.
      if (!out.flush()) throw std::runtime_error(std::string("cannot write the output: ") + std::strerror(errno));
      return code;
    } catch (const UsageError& e) {
      err << "postproc " << c.name << ": " << e.message << "\nusage: " << c.usage << '\n';
      return kUsage;
    } catch (const std::exception& e) {
      err << e.what() << '\n';
      return kBadInput;
    }
  }
  err << "postproc: unknown command `" << first << "`; see `postproc --help`\n";
  return kUsage;
}

}  // namespace postproc::cli
