// `postproc explain JOB.trace --post P.gpp`: each output line beside the command and the procedure
// that produced it.
#include <fmt/format.h>

#include <ostream>

#include "postproc/cli/cli.hpp"
#include "postproc/cli/cli_support.hpp"
#include "postproc/cli/explain_html.hpp"
#include "postproc/engine/slot_marker.hpp"

namespace postproc::cli {
namespace {

class Explainer final : public LineObserver {
public:
  Explainer(std::ostream& out, std::string post) : out_(out), post_(std::move(post)) {}
  void on_line(const LineEvent& e) override {
    if (e.file != file_) {
      file_ = std::string(e.file);
      line_ = 0;
      out_ << "==> " << file_ << " <==\n";
    }
    // A number known only later (start_line/end_line) shows as {?N} until its line below.
    const std::string text = slot::readable(e.text);
    std::string left = e.directive ? fmt::format("     {}", text) : fmt::format("{:>4} {}", ++line_, text);
    std::string right;
    if (!e.origin.command.empty()) right = fmt::format("#{} {}", e.origin.command_index, e.origin.command);
    if (!e.origin.procedure.empty())
      right += fmt::format("{}{} ({}:{})", right.empty() ? "" : " -> ", e.origin.procedure,
                           e.origin.include_file.empty() ? std::string_view(post_) : e.origin.include_file,
                           e.origin.source_line);
    if (e.directive) right += "  [directive]";
    out_ << fmt::format("{:<44} | {}\n", left, right);
  }

  void on_slot_filled(std::uint32_t slot, std::string_view text) override {
    out_ << fmt::format("     {{?{}}} = {}\n", slot, text);
  }

private:
  std::ostream& out_;
  std::string post_;
  std::string file_;
  std::size_t line_ = 0;
};

int run_explain(const Arguments& args, std::ostream& out, std::ostream& err) {
  if (args.positional().size() != 1) throw UsageError{"expected one job file"};
  EngineOptions engine_opts = engine_options(args, &err);
  Engine engine(engine_opts);
  print_machine_warnings(engine, err);
  Input input = Input::open(args.positional()[0]);
  OutputFiles files(".", OutputFiles::LineEnd::LF, true);
  Explainer explainer(out, std::filesystem::path(engine_opts.post).filename().string());
  ExplainPage page(args.positional()[0], engine_opts.post);
  const bool html = args.has("--html");
  RunOptions options = run_options(input, err);
  TraceOutput trace(args, err);
  trace.apply(options);
  if (html) {
    options.observer = &page;
    options.posted = [&page](const toolpath::Command& c) { page.posted(c); };
  } else {
    options.observer = &explainer;
  }
  Progress progress(err, args.has("--quiet"), input, args.has("--progress"));
  options.progress = [&](std::size_t n) { progress.update(n); };
  engine.run(*input.reader, files, options);
  if (html) {
    write_file_replacing(args.value("--html"), page.html());
    out << fmt::format("{}: wrote {}\n", args.positional()[0], args.value("--html"));
  }
  return kOk;
}

}  // namespace

Subcommand explain_command() {
  std::vector<OptionSpec> options = engine_option_specs();
  options.push_back({"--quiet", "-q", false, "no progress bar and no `input` log lines"});
  options.push_back({"--html", "", true, "write a self-contained page instead: NC lines, the post's source and a plot, linked"});
  return {
      "explain",
      "postproc explain --post P.gpp [--prp P.prp] [--html PAGE.html] JOB.trace",
      "Post a job and print each output line beside the command and GPP procedure that produced it.",
      options,
      run_explain,
  };
}

}  // namespace postproc::cli
