// The filters of the chain hand each command on together with its kind (command_kind of its name),
// so that a command's name is classified once, where it enters the chain or where a filter makes or
// renames it, instead of once in every filter.
//
//   class MyFilter final : public KindSource {
//     bool next_with_kind(toolpath::Command& out, CommandKind& kind) override {
//       if (!input_.next(out, kind)) return false;  // input_ is a KindedInput
//       ...                                          // rename out? then set kind as well
//     }
//   };
#pragma once

#include "prp/filters/command_kind.hpp"
#include "toolpath/source.hpp"

namespace prp {

struct CommandFields;

class KindSource : public toolpath::CommandSource {
public:
  // As next(out), and sets `kind` to command_kind(out) for the command handed out.
  virtual bool next_with_kind(toolpath::Command& out, CommandKind& kind) = 0;
  bool next(toolpath::Command& out) final {
    CommandKind kind;
    return next_with_kind(out, kind);
  }
  // The fields of the command handed out last, when this source found them for it (else null).
  // They hold while that command's parameter list keeps its length and order.
  const CommandFields* fields() const { return fields_; }

protected:
  const CommandFields* fields_ = nullptr;
};

// A filter's input: a KindSource tells the kind; the commands of any other source (the trace
// reader, a test's list) are classified here.
class KindedInput {
public:
  explicit KindedInput(toolpath::CommandSource& source)
      : source_(source), kinded_(dynamic_cast<KindSource*>(&source)) {}
  bool next(toolpath::Command& out, CommandKind& kind) {
    if (kinded_) return kinded_->next_with_kind(out, kind);
    if (!source_.next(out)) return false;
    kind = memo_(out.name);
    return true;
  }
  const CommandFields* fields() const { return kinded_ ? kinded_->fields() : nullptr; }

private:
  toolpath::CommandSource& source_;
  KindSource* kinded_;
  KindMemo memo_;
};

}  // namespace prp
