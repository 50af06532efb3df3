// Who produced an output line: the engine reports it with every line (LineEvent), and the
// regression comparer names it in its report. Kept apart so the engine need not include the
// comparer.
#pragma once

#include <cstddef>
#include <string_view>

namespace postproc {

// Who produced an output line.
struct LineOrigin {
  std::size_t command_index = 0;  // position of the stream command, from 0
  std::string_view command;       // "@arc"
  std::string_view procedure;     // the GPP procedure that started the line ("@arc", "@rapid_move")
  int source_line = 0;            // its line in the post
  // The file of source_line when it is not the post itself: an include file, by its path
  // relative to the post's folder (as `include` names it, usually).
  std::string_view include_file;
};

}  // namespace postproc
