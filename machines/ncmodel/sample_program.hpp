// A long, typical milling program in block G-code (contours of lines and half circles at depths
// stepping down, plunges, rapids, a comment per contour), for the controllers' benchmarks
// (machines::Controller::write_sample_program, bench/controller_bench.cpp). Only the blocks: the
// controller writes its own program frame around them.
#pragma once

#include <cstddef>
#include <ostream>

namespace ncmodel {

enum class CommentStyle { Parentheses, Semicolon };

// `blocks` blocks, numbered N10, N20, ...; the same program for the same arguments.
void write_milling_blocks(std::ostream& out, std::size_t blocks, CommentStyle comments);

}  // namespace ncmodel
