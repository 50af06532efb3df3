// A long 2XAxisCNC program of about `frames` frames, for the reading benchmark.
#pragma once

#include <cstddef>
#include <ostream>

namespace twoaxis {

void write_sample_program(std::ostream& out, std::size_t frames);

}  // namespace twoaxis
