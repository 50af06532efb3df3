// A synthetic milling job of any length, generated on the fly (nothing is kept): a tool change,
// then `motions` commands alternating @line and @arc around a stepped contour, as SolidCAM sends
// them (every motion carries xpos/ypos/zpos/feed; arcs their centre, radius, angles, direction).
#pragma once

#include <cstddef>

#include "toolpath/source.hpp"

namespace bench {

class SyntheticJob final : public toolpath::CommandSource {
public:
  explicit SyntheticJob(std::size_t motions) : motions_(motions) {}
  bool next(toolpath::Command& out) override;

private:
  std::size_t motions_;
  std::size_t step_ = 0;   // position in the whole job (header, motions, trailer)
  std::size_t index_ = 0;  // command index
};

}  // namespace bench
