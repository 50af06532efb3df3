// Internal: the PRP loader (one pass over the lines, collecting every diagnostic).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "prp/catalogue.hpp"
#include "prp/prp.hpp"

namespace prp {

// A blank-separated token of a value, with its 1-based column.
struct Token {
  std::string_view text;
  std::size_t column = 0;
};

class Loader {
public:
  Loader(std::string file_name, Units units);
  MachineParameters run(std::string_view text);

  // Parses `value` as `info` says into `out` (also used for engine defaults). False on error.
  bool parse_scalar(const KeyInfo& info, std::string_view value, std::size_t column, Parameter& out);

private:
  void line(std::string_view original, std::size_t number);
  void assignment(std::string_view original, std::string_view key, std::size_t key_column,
                  std::size_t value_begin, std::size_t value_end);
  void record(std::string_view base, std::string_view lang, std::string_view key, std::string_view value,
              std::size_t column);
  void check_ranges();
  void fill_defaults();

  void error(std::size_t column, std::string message, std::size_t line = 0);
  void warning(std::size_t column, std::string message, std::size_t line = 0);
  toolpath::SourcePosition at(std::size_t column, std::size_t line = 0) const;

  MachineParameters params_;
  std::vector<Diagnostic> errors_;
  std::size_t line_ = 0;
  enum class State { BeforeHeader, Body, AfterEnd } state_ = State::BeforeHeader;
};

// Splits a value into blank-separated tokens; `split_commas` makes every ',' a token of its own.
std::vector<Token> tokenize(std::string_view value, std::size_t column, bool split_commas = false);

}  // namespace prp
