#include "machines/sinumerik/controller.hpp"

#include <array>

#include "machines/ncmodel/sample_program.hpp"
#include "machines/registry/report_at_end.hpp"
#include "machines/sinumerik/reader.hpp"

namespace sinumerik {
namespace {

Options reader_options(const machines::ReadOptions& read) {
  Options options;
  if (read.max_blocks) options.max_executed_blocks = read.max_blocks;
  return options;
}

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
    return std::make_unique<machines::ReportAtEnd<SinumerikReader>>(SinumerikReader::open(path, reader_options(read)), warnings);
  }
  std::unique_ptr<machines::ProgramSource> open_text(std::string text, const std::string& name, std::string_view dialect,
                                                     const machines::ReadOptions& read,
                                                     std::ostream& warnings) const override {
    (void)dialect;
    return std::make_unique<machines::ReportAtEnd<SinumerikReader>>(
        SinumerikReader::from_string(std::move(text), name, reader_options(read)), warnings);
  }
  bool write_sample_program(std::ostream& out, std::size_t blocks) const override {
    out << "; BENCHMARK\nG71 G90 G17\nT1 M6\nS12000 M3\nG0 X0 Y0 Z5\n";
    ncmodel::write_milling_blocks(out, blocks, ncmodel::CommentStyle::Semicolon);
    out << "M5\nM30\n";
    return true;
  }
};

}  // namespace

const machines::Controller& controller() {
  static const Sinumerik instance;
  return instance;
}

}  // namespace sinumerik
