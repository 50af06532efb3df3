// The ProgramSource every controller model hands out: its reader's commands, then, when the program
// ends, every diagnostic printed (a diagnostic without a file is the program's own), and when any
// was an error (the motion is not the program's: a block was skipped) the first error thrown with
// its position. Reader: next(Command&), line() (of the program; 0 elsewhere), file_name(),
// diagnostics() -> const toolpath::Diagnostics&. Left before the end (verify stops at the first
// divergence), it prints what the model found so far: often the reason for the divergence.
#pragma once

#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "machines/registry/controller.hpp"
#include "toolpath/diagnostic.hpp"

namespace machines {

template <class Reader>
class ReportAtEnd final : public ProgramSource {
public:
  ReportAtEnd(std::unique_ptr<Reader> reader, std::ostream& warnings) : reader_(std::move(reader)), warnings_(warnings) {}
  ~ReportAtEnd() override {
    if (!reported_) print(reader_->diagnostics(), reader_->file_name());
  }
  ReportAtEnd(const ReportAtEnd&) = delete;
  ReportAtEnd& operator=(const ReportAtEnd&) = delete;

  bool next(toolpath::Command& out) override {
    if (reader_->next(out)) return true;
    if (!reported_) {
      reported_ = true;
      report(reader_->diagnostics(), reader_->file_name());
    }
    return false;
  }
  std::size_t line() const override { return reader_->line(); }

private:
  static toolpath::Diagnostic placed(toolpath::Diagnostic d, const std::string& program) {
    if (d.where.file.empty()) d.where.file = program;
    return d;
  }
  void print(const toolpath::Diagnostics& all, const std::string& program) {
    for (const auto& d : all.kept()) warnings_ << placed(d, program).text() << '\n';
    if (all.total() > all.kept().size())
      warnings_ << fmt::format("{}: {} more diagnostics not shown\n", program, all.total() - all.kept().size());
  }
  void report(const toolpath::Diagnostics& all, const std::string& program) {
    print(all, program);
    if (all.errors() == 0) return;
    const toolpath::Diagnostic* first = all.first_error();
    if (!first) throw toolpath::InputError({program, 0, 0}, fmt::format("{} error(s) in the program", all.errors()));
    const toolpath::Diagnostic e = placed(*first, program);
    throw toolpath::InputError(e.where, fmt::format("{} error(s) in the program; the first: {}", all.errors(), e.message));
  }

  std::unique_ptr<Reader> reader_;
  std::ostream& warnings_;
  bool reported_ = false;
};

}  // namespace machines
