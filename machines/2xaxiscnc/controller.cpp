#include "machines/2xaxiscnc/controller.hpp"

#include <array>

#include "machines/2xaxiscnc/reader.hpp"
#include "machines/2xaxiscnc/sample_program.hpp"
#include "machines/registry/report_at_end.hpp"
#include "toolpath/value.hpp"

namespace twoaxis {
namespace {

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

// The program has no loops: max_blocks has nothing to bound (scripts are files, not read from memory).
Options reader_options(const machines::ReadOptions& read) {
  Options options;
  if (read.for_verify) {
    double rapid = 1;
    from_answers(read, options.machine_speed, rapid);
    options.rapid_coefficient = 0;  // every frame a @line at its coefficient's feed
  }
  return options;
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
    return std::make_unique<machines::ReportAtEnd<TwoAxisReader>>(TwoAxisReader::open(path, reader_options(read)), warnings);
  }
  std::unique_ptr<machines::ProgramSource> open_text(std::string text, const std::string& name, std::string_view dialect,
                                                     const machines::ReadOptions& read,
                                                     std::ostream& warnings) const override {
    (void)dialect;
    return std::make_unique<machines::ReportAtEnd<TwoAxisReader>>(
        TwoAxisReader::from_string(std::move(text), name, reader_options(read)), warnings);
  }
  machines::VerifyProfile verify_profile(const machines::ReadOptions& read) const override {
    machines::VerifyProfile p;
    p.planar_speeds = true;
    p.machine_speed = Options{}.machine_speed;
    from_answers(read, p.machine_speed, p.rapid_coefficient);
    return p;
  }
  bool write_sample_program(std::ostream& out, std::size_t blocks) const override {
    twoaxis::write_sample_program(out, blocks);
    return true;
  }
};

}  // namespace

const machines::Controller& controller() {
  static const TwoAxisCnc instance;
  return instance;
}

}  // namespace twoaxis
