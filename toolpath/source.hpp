// A pull-based stream of commands. Readers, PRP filters and controller models are all sources,
// each filter wrapping another, so a job streams from file to NC output one command at a time.
#pragma once

#include <memory>
#include <optional>

#include "toolpath/command.hpp"

namespace toolpath {

class CommandSource {
public:
  virtual ~CommandSource() = default;
  // Fills `out` with the next command and returns true, or returns false at the end.
  // `out` is reused between calls: implementations overwrite it and keep its capacity.
  virtual bool next(Command& out) = 0;
};

// Wraps a source so that the following command can be looked at before it is taken
// (the engine sets `next_command` from it).
class LookaheadSource final : public CommandSource {
public:
  explicit LookaheadSource(CommandSource& inner) : inner_(inner) { buffered_.keep_name_on_heap(); }
  bool next(Command& out) override;
  // The command the next call to next() returns, or nullptr at the end of the stream.
  const Command* peek();

private:
  CommandSource& inner_;
  Command buffered_;
  bool has_buffered_ = false;
  bool at_end_ = false;
};

}  // namespace toolpath
