// Output directives: generated lines such as `!!open file=NAME!!` or `!! close file = NAME !!` that
// switch, delete or copy output files instead of being written (solidcam-behaviour.md section 2,
// gppl-language.md section 6.7).
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace postproc {

struct Directive {
  enum class Verb : std::uint8_t { Open, Close, Delete, Copy, MakeDir };
  Verb verb = Verb::Open;
  std::string name;  // the file or folder named, blanks around it removed
};

std::string_view verb_name(Directive::Verb verb);

// A line that starts and ends with `!!` but does not say `<verb> file = NAME` (or `make dir = NAME`).
class DirectiveError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The directive on `line`, or nullopt when the line is ordinary output. Blanks are allowed before,
// after and inside the `!!` pair. Throws DirectiveError for a `!! ... !!` line it cannot read.
std::optional<Directive> parse_directive(std::string_view line);

}  // namespace postproc
