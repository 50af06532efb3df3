// start_line / end_line (gpptool-commands.md 2.8, 2.11, 6.3-6.9, 13.1-13.5): the first and last
// block numbers of the body a command belongs to. The body usually comes after the line that
// prints its numbers (a subroutine body after the call, a loop body after @loop), so a number not
// known yet is written as a placeholder and filled in when its body closes.
//
// Bodies: a subroutine `@proc` ... `@end_proc` (also `@turn_proc` ... `@turn_endproc`, turning
// geometry; one label space), or a loop `@loop` ... `@end_loop`. A body's blocks are the numbered
// blocks written after its opening procedure returned and before its closing procedure started:
// the delimiters' own blocks (an `O` header, `M99`, the loop's `G14`) are not part of it.
//
// Memory: the open bodies, the placeholders not yet resolved, and one range per subroutine label.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "gppl/gppl.hpp"

namespace postproc {

class BlockRanges {
public:
  // What a command (or the procedure of the same name) is to the body structure.
  enum class Role : std::uint8_t { None, OpenSubroutine, CloseSubroutine, OpenLoop, CloseLoop, CallByLabel };
  static Role role_of(std::string_view command);

  // new_slot(marker) reserves a placeholder and returns its id; fill(id, text) resolves it.
  using NewSlot = std::function<std::uint32_t(std::string& marker)>;
  using Fill = std::function<void(std::uint32_t id, std::string_view text)>;
  BlockRanges(NewSlot new_slot, Fill fill);

  // A procedure of role `role` starts or ends (the engine's call or a `call` statement); a stream
  // command without a procedure does both at once. `label` is the value of `label` at that moment.
  void enter(Role role, std::int64_t label);
  void leave(Role role);
  // `nb` wrote block number `number`.
  void block_numbered(std::int64_t number);
  // The text of start_line/end_line for the innermost running procedure with a role: the number
  // under `format`, or a placeholder. `label` is the value of `label` now; `where` names the item
  // for messages. Throws std::runtime_error when there is no such body or it has no numbered blocks.
  void line_function(gppl::LineFunction which, std::string_view format, std::int64_t label, std::string where,
                     std::string& out);
  // End of the run: throws for the first placeholder whose body never came.
  void finish() const;

private:
  enum class Kind : std::uint8_t { Subroutine, Loop };
  struct Range {
    std::optional<std::int64_t> first, last;
  };
  struct Pending {
    std::uint32_t slot = 0;
    gppl::LineFunction which{};
    std::string format;
    std::string where;
  };
  struct Body {
    Kind kind{};
    std::int64_t label = 0;
    std::uint64_t id = 0;
    bool recording = false;  // false while its opening procedure still runs
    Range range;
    std::vector<Pending> waiting;
  };
  struct Running {
    Role role = Role::None;
    std::uint64_t body = 0;  // openers: the body they open
  };
  struct Closed {
    bool valid = false;
    std::int64_t label = 0;
    Range range;
  };

  static Kind kind_of(Role role);
  static std::string describe(Kind kind, std::int64_t label);
  Body* find_open(std::uint64_t id);
  void close(Kind kind);
  void resolve(const Pending& p, const Range& range, const std::string& body) const;
  void defer(std::vector<Pending>& into, gppl::LineFunction which, std::string_view format, std::string where,
             std::string& out);

  NewSlot new_slot_;
  Fill fill_;
  std::vector<Body> open_;          // innermost last
  std::vector<Running> running_;    // procedures with a role, innermost last
  std::unordered_map<std::int64_t, Range> closed_subroutines_;
  std::unordered_map<std::int64_t, std::vector<Pending>> awaiting_label_;  // calls before their body
  Closed last_closed_[2];
  std::uint64_t next_body_ = 1;
};

}  // namespace postproc
