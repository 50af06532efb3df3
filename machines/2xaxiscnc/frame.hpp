// One line of a 2XAxisCNC program split into its commands, and the one-command instructions.
// The number of commands decides what a frame is (docs/2xaxiscnc.md, "Frames").
#pragma once

#include <cstddef>
#include <string_view>

namespace twoaxis {

struct Frame {
  static constexpr std::size_t kKept = 4;  // a fourth command is enough to reject the frame
  std::string_view commands[kKept];
  std::size_t columns[kKept] = {};  // 1-based byte column of each kept command
  std::size_t count = 0;            // every command of the line, also those not kept
};

// Splits on runs of blanks (space, tab, stray CR); leading and trailing blanks are ignored.
Frame split_frame(std::string_view line);

enum class Instruction {
  Unknown, Comment, HomeXY, GotoZero, SpindleToggle, SpindleOn, SpindleOff, Relay, Pause,
  ArtCamMarker, G90Marker, G91Marker, Pulses, AMove, HomeA, Script,
};

struct Classified {
  Instruction kind = Instruction::Unknown;
  bool case_differs = false;  // matched only ignoring case (`m03`): accepted with a warning
  std::string_view argument;  // Pause, AMove: the number; Comment: the text; Script: the name;
                              // Pulses: `pin_interval_count`; Relay: the digit
  std::size_t argument_offset = 0;  // where `argument` starts inside the command
};

// What a one-command frame is. Unknown when it is nothing the format defines.
Classified classify(std::string_view command);

}  // namespace twoaxis
