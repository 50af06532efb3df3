#include "machines/sinumerik/controller.hpp"

#include <fmt/format.h>

#include <array>

#include "machines/sinumerik/reader.hpp"
#include "toolpath/error.hpp"

namespace sinumerik {
namespace {

// Every diagnostic is printed when the program ends; errors (blocks that could not be executed: the
// motion is not the program's) then fail with the first error's position.
class Reporting final : public machines::ProgramSource {
public:
  Reporting(std::unique_ptr<SinumerikReader> reader, std::ostream& warnings) : reader_(std::move(reader)), warnings_(warnings) {}
  bool next(toolpath::Command& out) override {
    if (reader_->next(out)) return true;
    if (reported_) return false;
    reported_ = true;
    const Diagnostic* first_error = nullptr;
    for (const auto& d : reader_->diagnostics()) {
      if (d.error && !first_error) first_error = &d;
      warnings_ << fmt::format("{}:{}:{}: {}: {}\n", d.file, d.line, d.column, d.error ? "error" : "warning", d.message);
    }
    const std::size_t hidden = reader_->diagnostic_count() - reader_->diagnostics().size();
    if (hidden > 0) warnings_ << fmt::format("{}: {} more diagnostics not shown\n", reader_->file_name(), hidden);
    if (reader_->error_count() > 0) {
      const Diagnostic& e = first_error ? *first_error : reader_->diagnostics().front();
      throw toolpath::InputError({e.file, e.line, e.column},
                                 fmt::format("{} error(s) in the program; the first: {}", reader_->error_count(), e.message));
    }
    return false;
  }
  std::size_t line() const override { return reader_->line(); }

private:
  std::unique_ptr<SinumerikReader> reader_;
  std::ostream& warnings_;
  bool reported_ = false;
};

class Sinumerik final : public machines::Controller {
public:
  std::span<const std::string_view> names() const override {
    static constexpr std::array<std::string_view, 3> kNames = {"sinumerik", "828d", "840d"};
    return kNames;
  }
  std::string_view title() const override { return "Sinumerik"; }
  std::string_view summary() const override {
    return "Siemens Sinumerik 828D/840D: N blocks, R parameters and DEF variables, CR= and AC/IC, CYCLE81-89 and "
           "MCALL, EXTCALL and L subprograms, GOTOB/GOTOF";
  }
  std::unique_ptr<machines::ProgramSource> open(const std::string& path, std::string_view dialect,
                                                const machines::ReadOptions& read, std::ostream& warnings) const override {
    (void)dialect;
    (void)read;
    return std::make_unique<Reporting>(SinumerikReader::open(path), warnings);
  }
};

}  // namespace

const machines::Controller& controller() {
  static const Sinumerik instance;
  return instance;
}

}  // namespace sinumerik
