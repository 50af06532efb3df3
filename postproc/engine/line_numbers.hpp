// Connects start_line/end_line to a run (docs/engine.md, "start_line and end_line"): the
// interpreter's structure hooks go to BlockRanges, its placeholders to the output files, and each
// placeholder's final text to the line observer (so `postproc test` compares the finished line).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>

#include "gppl/gppl.hpp"
#include "postproc/engine/block_ranges.hpp"
#include "postproc/engine/engine.hpp"

namespace postproc {

class LineNumbers {
public:
  // `command` names the command being posted, for messages ("command #3 @call_proc").
  LineNumbers(gppl::Interpreter& interpreter, OutputFiles& files, LineObserver* observer,
              std::function<std::string()> command);

  void block_numbered(std::int64_t number) { ranges_.block_numbered(number); }
  void procedure_boundary(gppl::ProcedureId id, bool entering);
  // A stream command the post has no procedure for still opens or closes its body.
  void command_without_procedure(std::string_view name);
  void line_function(gppl::LineFunction which, std::string_view format, const gppl::Position& item, std::string& out);
  void finish() const { ranges_.finish(); }

private:
  std::int64_t label() const;

  gppl::Interpreter& interpreter_;
  std::function<std::string()> command_;
  std::optional<gppl::VariableId> label_;
  std::unordered_map<gppl::ProcedureId, BlockRanges::Role> roles_;
  BlockRanges ranges_;
};

}  // namespace postproc
