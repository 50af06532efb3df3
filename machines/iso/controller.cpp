#include "machines/iso/controller.hpp"

#include <array>

#include "machines/iso/reader.hpp"
#include "machines/ncmodel/sample_program.hpp"
#include "machines/registry/report_at_end.hpp"

namespace iso {
namespace {

// One registry entry per dialect: the names it answers to and the rules its reader applies.
template <std::size_t N>
class IsoController final : public machines::Controller {
public:
  constexpr IsoController(std::array<std::string_view, N> names, std::string_view title, std::string_view summary)
      : names_(names), title_(title), summary_(summary) {}
  std::span<const std::string_view> names() const override { return names_; }
  std::string_view title() const override { return title_; }
  std::string_view summary() const override { return summary_; }
  std::unique_ptr<machines::ProgramSource> open(const std::string& path, std::string_view dialect,
                                                const machines::ReadOptions& read, std::ostream& warnings) const override {
    (void)dialect;
    return std::make_unique<machines::ReportAtEnd<IsoReader>>(IsoReader::open(path, rules(), reader_options(read)), warnings);
  }
  std::unique_ptr<machines::ProgramSource> open_text(std::string text, const std::string& name, std::string_view dialect,
                                                     const machines::ReadOptions& read,
                                                     std::ostream& warnings) const override {
    (void)dialect;
    return std::make_unique<machines::ReportAtEnd<IsoReader>>(
        IsoReader::from_string(std::move(text), name, rules(), reader_options(read)), warnings);
  }
  machines::VerifyProfile verify_profile(const machines::ReadOptions& read) const override {
    (void)read;
    machines::VerifyProfile profile;
    profile.tool_changes = rules_of(names_.front())->tool_change;
    return profile;
  }
  bool write_sample_program(std::ostream& out, std::size_t blocks) const override {
    const Rules& rules = *rules_of(names_.front());
    if (rules.subprograms) out << "%\nO1000 (BENCHMARK)\n";
    out << "G21 G90 G17\n" << (rules.tool_change ? "T1 M6\n" : "") << "S12000 M3\nG0 X0 Y0 Z5.\n";
    ncmodel::write_milling_blocks(out, blocks, ncmodel::CommentStyle::Parentheses);
    out << "M5\nM30\n" << (rules.subprograms ? "%\n" : "");
    return true;
  }

private:
  const Rules& rules() const { return *rules_of(names_.front()); }
  static Options reader_options(const machines::ReadOptions& read) {
    Options options;
    if (read.max_blocks) options.max_executed_blocks = read.max_blocks;
    if (!read.tool_table.empty())
      options.tools = std::make_shared<const ncmodel::ToolTable>(ncmodel::load_tool_table(read.tool_table));
    return options;
  }

  std::array<std::string_view, N> names_;
  std::string_view title_, summary_;
};

}  // namespace

const machines::Controller& fanuc() {
  static const IsoController<3> instance({"fanuc", "haas", "0i"}, "Fanuc",
                                         "Fanuc 0i/31i mills (and Haas): G73/G81-G89 with G98/G99, M98/M99 and O "
                                         "numbers, custom macro B (#n, WHILE DO/END), G4 P in ms");
  return instance;
}

const machines::Controller& linuxcnc() {
  static const IsoController<2> instance({"linuxcnc", "pocketnc"}, "LinuxCNC",
                                         "LinuxCNC 2.8+: G73/G81-G89, o-word sub/call/repeat, M98/M99, G4 P in seconds");
  return instance;
}

const machines::Controller& mach3() {
  static const IsoController<2> instance({"mach3", "mach4"}, "Mach3",
                                         "Mach3/Mach4 mills: G73/G81-G89 with G98/G99, M98/M99 and O numbers, G4 P in "
                                         "seconds");
  return instance;
}

const machines::Controller& grbl() {
  static const IsoController<1> instance({"grbl"}, "GRBL",
                                         "GRBL 1.1: G0-G3, G17-G19, G90/G91, G20/G21, G28/G30/G53, G4 P in seconds; no "
                                         "canned cycles, tool changes or subprograms");
  return instance;
}

}  // namespace iso
