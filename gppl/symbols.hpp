// What an editor needs of a post's names: every variable and procedure, where it is declared and
// every place it is used, as one compile resolves them (so go to definition, references, rename and
// hover agree with the compiler, never a second opinion). Filled when CompileOptions::symbols is
// set, also by a compile that fails: what resolved before the errors is there.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gppl/gppl.hpp"

namespace gppl {

enum class SymbolKind : std::uint8_t {
  System,     // a name SolidCAM predefines (find_system_variable has its documentation)
  Host,       // declared by the host: a command parameter or a PRP external variable
  Global,     // the post's `global`
  Local,      // a `local` or a parameter of one procedure
  Procedure,  // "@line", "@my_sub"
};

struct Symbol {
  std::string name;  // as first written
  SymbolKind kind = SymbolKind::Global;
  Type type = Type::Integer;   // variables
  std::vector<int> dimensions; // variables: empty for a scalar
  std::uint32_t procedure = 0; // Local: the symbol of its procedure
  bool declared = false;       // `where` is its declaration (System and Host names have none)
  Position where;              // declaration, else its first use
};

struct SymbolUse {
  std::uint32_t symbol = 0;
  std::uint32_t file = 0;  // index into SymbolIndex::files
  std::uint32_t line = 0, column = 0, length = 0;  // 1-based line and column, length in bytes
  bool declaration = false;
};

struct SymbolIndex {
  std::vector<std::string> files;  // the main file, then each include as loaded
  std::vector<Symbol> symbols;
  std::vector<SymbolUse> uses;     // in compile order (by procedure, then line)
};

}  // namespace gppl
