// `postproc explain --html FILE`: one self-contained page (no network, no external script) with the
// NC program, each line linked to the GPP line and the toolpath command that produced it, the post's
// source (and its include files') with the lines that wrote output marked, and XY and XZ plots of the toolpath where a click
// on a line highlights its segment and a click on a segment selects its line. Lists are
// virtualised, so a 200 000-line program opens and scrolls as a short one (docs/engine.md, "explain").
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "postproc/engine/engine.hpp"
#include "toolpath/command.hpp"

namespace postproc::cli {

class ExplainPage final : public LineObserver {
public:
  ExplainPage(std::string job, std::string post_path);
  void on_line(const LineEvent& e) override;
  void on_slot_filled(std::uint32_t slot, std::string_view text) override;
  // Each command the post received (RunOptions::posted): its motion becomes plot segments.
  void posted(const toolpath::Command& c);
  // The page. A self-test hook in it (`#select=N`, `#plotclick=C`) is what the browser test drives.
  std::string html() const;

private:
  struct Line {
    std::string text;
    std::int64_t command = -1;  // toolpath command index, -1: none
    std::uint32_t procedure = 0;  // into procedures_
    std::uint32_t gpp_line = 0;
    std::uint32_t source = 0;  // into sources_: 0 the post, else an include file
  };
  struct File {
    std::string name;
    std::vector<Line> lines;
  };
  void segment(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool rapid, std::size_t command);

  std::string job_, post_path_;
  std::vector<File> files_;
  std::vector<std::string> procedures_{""};
  std::vector<std::string> sources_{""};  // include files by their name relative to the post's folder
  std::map<std::string, std::uint32_t, std::less<>> source_ids_{{"", 0}};
  std::map<std::string, std::uint32_t, std::less<>> procedure_ids_{{"", 0}};
  std::map<std::uint32_t, std::string> slots_;
  std::size_t current_ = 0;       // the file the last line went to
  std::vector<double> segments_;  // x0 y0 z0 x1 y1 z1 per segment
  std::vector<std::uint32_t> segment_commands_;
  std::vector<std::uint8_t> segment_rapid_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  bool position_known_ = false;
};

}  // namespace postproc::cli
