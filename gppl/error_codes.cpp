// The GPPTool error catalogue (spec section 13.2), with the translation's garbling normalised.
#include "gppl/error_codes.hpp"

#include <fmt/format.h>

namespace gppl {

namespace {

struct Entry {
  ErrorCode code;
  const char* before;  // text before the symbol name (or the whole text)
  const char* after;   // text after the symbol name; nullptr: the text names no symbol
};

constexpr Entry kCatalogue[] = {
    {ErrorCode::MissingEndif, "ENDIF statement missing", nullptr},
    {ErrorCode::NotDefined, "Variable", "is not defined"},
    {ErrorCode::TooComplex, "Program too complex", nullptr},
    {ErrorCode::Unrecognized, "Unrecognized statement", nullptr},
    {ErrorCode::NotNumeric, "Variable", "is not numeric"},
    {ErrorCode::OutOfRange, "Argument of function out of range", nullptr},
    {ErrorCode::MissingEndp, "ENDP statement missing", nullptr},
    {ErrorCode::InvalidAssignment, "Invalid ASSIGNMENT statement", nullptr},
    {ErrorCode::InvalidGenerate, "Invalid GENERATE statement", nullptr},
    {ErrorCode::InvalidCall, "Invalid CALL statement", nullptr},
    {ErrorCode::InvalidIf, "Invalid IF statement", nullptr},
    {ErrorCode::NotString, "Variable", "is not string variable"},
    {ErrorCode::ProcDefined, "Proc", "already defined"},
    {ErrorCode::CantOpen, "Can't open file", ""},
    {ErrorCode::InvalidGlobal, "Invalid GLOBAL statement", nullptr},
    {ErrorCode::InvalidLocal, "Invalid LOCAL statement", nullptr},
    {ErrorCode::ReadOnly, "Symbol", "can't be modified"},
    {ErrorCode::SymbolTableFull, "Symbol table is full", nullptr},
    {ErrorCode::DoesNotExist, "Symbol", "does not exist"},
    {ErrorCode::StackOverflow, "Stack overflow", nullptr},
    {ErrorCode::ZeroDivide, "Zero divide", nullptr},
    {ErrorCode::FormatNoDigit, "Format: without any digit", nullptr},
    {ErrorCode::FormatScale, "Format: scale factor invalid", nullptr},
    {ErrorCode::ValueRange, "Val: number out of range", nullptr},
    {ErrorCode::GlobalRedefined, "Global variable", "is multiply defined"},
    {ErrorCode::LocalRedefined, "Local variable", "is multiply defined"},
    {ErrorCode::AlreadyLocal, "Variable", "is already declared as local"},
    {ErrorCode::AlreadyGlobal, "Variable", "is already declared as global"},
    {ErrorCode::SystemDeclared, "System variable", "can't be declared"},
    {ErrorCode::NotLogical, "Numeric expression is not of logical type", nullptr},
    {ErrorCode::FormatNoPoint, "Format: No decimal point", nullptr},
    {ErrorCode::FormatNoFraction, "Format: No fraction digits", nullptr},
    {ErrorCode::FormatOption, "Format: Invalid format option", nullptr},
    {ErrorCode::ReadError, "Error while reading file", ""},
    {ErrorCode::BlockNumberTooBig, "Block number field too big", nullptr},
};

}  // namespace

std::string error_text(ErrorCode code, std::string_view name) {
  for (const Entry& e : kCatalogue) {
    if (e.code != code) continue;
    if (e.after == nullptr) return e.before;
    const std::string quoted = name.empty() ? std::string() : fmt::format(" '{}'", name);
    return fmt::format("{}{}{}{}", e.before, quoted, *e.after != '\0' ? " " : "", e.after);
  }
  return "Unknown error";
}

Error make_error(ErrorCode code, Position where, std::string_view name, std::string_view detail) {
  const std::string text = detail.empty() ? error_text(code, name) : fmt::format("{}: {}", error_text(code, name), detail);
  return Error(static_cast<int>(code), std::move(where), text);
}

}  // namespace gppl
