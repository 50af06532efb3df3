#include "machines/pikocnc/model/controller.hpp"

#include <array>

#include "machines/ncmodel/sample_program.hpp"
#include "machines/ncmodel/tool_table.hpp"
#include "machines/pikocnc/model/dialect.hpp"
#include "machines/pikocnc/model/reader.hpp"
#include "machines/registry/report_at_end.hpp"
#include "toolpath/value.hpp"

namespace pikocnc {
namespace {

Options reader_options(std::string_view dialect, const machines::ReadOptions& read) {
  Options options;
  std::string lower(dialect);
  for (char& ch : lower) ch = toolpath::ascii_lower(ch);
  options.dialect = parse_dialect(lower).value_or(Dialect::V2025);
  options.nc_lines_in_trace = read.nc_lines_in_trace;
  if (read.for_verify) {
    options.comments_as_messages = false;
    options.cutter_compensation = false;  // the toolpath is the programmed contour
  }
  if (read.max_blocks) {  // a cycle makes a few commands a block; a tiny peck Q makes many
    options.max_executed_lines = read.max_blocks;
    options.max_commands = 4 * read.max_blocks;
  }
  if (!read.tool_table.empty())  // G41/G42 without R take the radius from it
    for (const auto& [number, t] : ncmodel::load_tool_table(read.tool_table).tools)
      if (number >= 0 && number <= 99'999'999) options.tools[static_cast<int>(number)].radius = t.diameter / 2;
  return options;
}

class PikoCnc final : public machines::Controller {
public:
  std::span<const std::string_view> names() const override {
    static constexpr std::array<std::string_view, 3> kNames = {"pikocnc", "pikocnc-2025", "pikocnc-2016"};
    return kNames;
  }
  std::string_view title() const override { return "PikoCNC"; }
  std::string_view summary() const override {
    return "PikoCNC (dialects 2025 and 2016): cycles, loops, transforms, offsets and cutter compensation expanded";
  }
  std::unique_ptr<machines::ProgramSource> open(const std::string& path, std::string_view dialect,
                                                const machines::ReadOptions& read, std::ostream& warnings) const override {
    return std::make_unique<machines::ReportAtEnd<PikoReader>>(PikoReader::open(path, reader_options(dialect, read)), warnings);
  }
  std::unique_ptr<machines::ProgramSource> open_text(std::string text, const std::string& name, std::string_view dialect,
                                                     const machines::ReadOptions& read,
                                                     std::ostream& warnings) const override {
    return std::make_unique<machines::ReportAtEnd<PikoReader>>(
        PikoReader::from_string(std::move(text), name, reader_options(dialect, read)), warnings);
  }
  machines::VerifyProfile verify_profile(const machines::ReadOptions& read) const override {
    (void)read;
    machines::VerifyProfile profile;
    profile.tap_feeds_out_to_r = false;  // G84 is for a self-reversing tapping head
    return profile;
  }
  bool write_sample_program(std::ostream& out, std::size_t blocks) const override {
    out << "Benchmark job\n%\nG21 G90 G17\nM6 T1\nS12000 M3\nG0 X0 Y0 Z5\n";
    ncmodel::write_milling_blocks(out, blocks, ncmodel::CommentStyle::Parentheses);
    out << "M5\nM30\n";
    return true;
  }
};

}  // namespace

const machines::Controller& controller() {
  static const PikoCnc instance;
  return instance;
}

}  // namespace pikocnc
