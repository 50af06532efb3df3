#include "machines/2xaxiscnc/controller.hpp"

#include <fmt/format.h>

#include <array>

#include "machines/2xaxiscnc/reader.hpp"
#include "toolpath/error.hpp"
#include "toolpath/value.hpp"

namespace twoaxis {
namespace {

// Every diagnostic is printed when the program ends; errors (frames skipped or clamped: the motion
// is not the program's) then fail with the first error's position.
class Reporting final : public machines::ProgramSource {
public:
  Reporting(std::unique_ptr<TwoAxisReader> reader, std::ostream& warnings) : reader_(std::move(reader)), warnings_(warnings) {}
  bool next(toolpath::Command& out) override {
    if (reader_->next(out)) return true;
    if (reported_) return false;
    reported_ = true;
    const Diagnostic* first_error = nullptr;
    for (const auto& d : reader_->diagnostics()) {
      const bool error = d.severity == Diagnostic::Severity::Error;
      if (error && !first_error) first_error = &d;
      warnings_ << fmt::format("{}:{}:{}: {}: {}\n", d.file.empty() ? reader_->file_name() : d.file, d.line, d.column,
                               error ? "error" : "warning", d.message);
    }
    const std::size_t hidden = reader_->diagnostic_count() - reader_->diagnostics().size();
    if (hidden > 0) warnings_ << fmt::format("{}: {} more diagnostics not shown\n", reader_->file_name(), hidden);
    if (reader_->error_count() > 0) {
      const auto& e = first_error ? *first_error : reader_->diagnostics().front();
      throw toolpath::InputError({e.file.empty() ? reader_->file_name() : e.file, e.line, e.column},
                                 fmt::format("{} error(s) in the program; the first: {}", reader_->error_count(), e.message));
    }
    return false;
  }

  std::size_t line() const override { return reader_->script_name().empty() ? reader_->line() : 0; }

private:
  std::unique_ptr<TwoAxisReader> reader_;
  std::ostream& warnings_;
  bool reported_ = false;
};

// The application's speed settings, as the post's answers give them (its defaults otherwise).
void from_answers(const machines::ReadOptions& read, double& machine_speed, double& rapid_coefficient) {
  for (const auto& [name, value] : read.answers) {
    double* field = toolpath::iequals(name, "machine_speed") ? &machine_speed
                    : toolpath::iequals(name, "rapid_coef")  ? &rapid_coefficient
                                                             : nullptr;
    if (!field) continue;
    try {
      *field = std::stod(value);
    } catch (const std::exception&) {
      // the post rejects the answer itself, naming its input statement
    }
  }
}

class TwoAxisCnc final : public machines::Controller {
public:
  std::span<const std::string_view> names() const override {
    static constexpr std::array<std::string_view, 1> kNames = {"2xaxiscnc"};
    return kNames;
  }
  std::string_view title() const override { return "2XAxisCNC"; }
  std::string_view summary() const override {
    return "2XAxisCNC: relative X/Y frames at speed coefficients, ArtCAM/G90 conversion, scripts";
  }
  std::unique_ptr<machines::ProgramSource> open(const std::string& path, std::string_view dialect,
                                                const machines::ReadOptions& read, std::ostream& warnings) const override {
    (void)dialect;
    Options options;
    if (read.for_verify) {
      double rapid = 1;
      from_answers(read, options.machine_speed, rapid);
      options.rapid_coefficient = 0;  // every frame a @line at its coefficient's feed
    }
    return std::make_unique<Reporting>(TwoAxisReader::open(path, options), warnings);
  }
  machines::VerifyProfile verify_profile(const machines::ReadOptions& read) const override {
    machines::VerifyProfile p;
    p.planar_speeds = true;
    p.machine_speed = Options{}.machine_speed;
    from_answers(read, p.machine_speed, p.rapid_coefficient);
    return p;
  }
};

}  // namespace

const machines::Controller& controller() {
  static const TwoAxisCnc instance;
  return instance;
}

}  // namespace twoaxis
