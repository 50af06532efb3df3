// Internal: the PRP loader (one pass over the lines, collecting every diagnostic).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "prp/params/catalogue.hpp"
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

  // The VMID reader (vmid.cpp) fills the same model from XML through these, with positions it
  // computes from byte offsets.
  MachineParameters run_vmid(std::string_view text);
  void error_at(toolpath::SourcePosition where, std::string message);
  void warning_at(toolpath::SourcePosition where, std::string message);
  // Adds a documented scalar; false (and nothing changes) when the key is already set.
  bool add_parameter(Parameter parameter);
  // Adds a record; an error (false) when its key and name are taken already.
  bool add_record(Record record);
  // Declares a PRP external variable once; an error (false) when it was declared with another type.
  bool declare(std::string_view name, VarType type, std::optional<toolpath::Value> initial, std::string_view by,
               toolpath::SourcePosition where);
  // A rotary axis of the machine definition; a second one of the same name is ignored.
  void add_rotary_limits(RotaryLimits limits);
  const std::string& file_name() const { return params_.file_; }

private:
  void line(std::string_view original, std::size_t number);
  void assignment(std::string_view original, std::string_view key, std::size_t key_column,
                  std::size_t value_begin, std::size_t value_end);
  void remember_unknown(std::string_view original, std::string_view key, std::size_t key_column,
                        std::size_t value_begin, std::size_t value_end);
  void record(std::string_view base, std::string_view lang, std::string_view key, std::string_view value,
              std::size_t column);
  void check_ranges();
  void fill_defaults();
  MachineParameters finish();  // range checks, defaults; throws LoadError when anything failed

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
