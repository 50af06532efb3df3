// The GPPTool error catalogue (numbers and message texts) and helpers that build gppl::Error from it.
#pragma once

#include <string>
#include <string_view>

#include "gppl/gppl.hpp"

namespace gppl {

// Numbers as GPPTool prints them. Only conditions this implementation can raise are listed.
enum class ErrorCode : int {
  MissingEndif = 194,        // also "ENDW statement missing" (same number, own text)
  NotDefined = 383,
  TooComplex = 384,
  Unrecognized = 385,
  NotNumeric = 386,
  OutOfRange = 387,
  MissingEndp = 388,
  InvalidAssignment = 389,
  InvalidGenerate = 390,
  InvalidCall = 391,
  InvalidIf = 392,
  NotString = 394,
  ProcDefined = 396,
  CantOpen = 399,
  InvalidGlobal = 400,
  InvalidLocal = 401,
  ReadOnly = 402,
  SymbolTableFull = 403,
  DoesNotExist = 404,
  StackOverflow = 405,
  ZeroDivide = 407,
  FormatNoDigit = 408,
  FormatScale = 409,
  ValueRange = 410,
  GlobalRedefined = 411,
  LocalRedefined = 412,
  AlreadyLocal = 415,
  AlreadyGlobal = 416,
  SystemDeclared = 418,
  NotLogical = 420,
  FormatNoPoint = 421,
  FormatNoFraction = 422,
  FormatOption = 423,
  ReadError = 426,
  BlockNumberTooBig = 452,
};

// The catalogue text. Texts that name a symbol ("Variable 'xxx' is not defined") take `name`;
// without a name the quoted part is left out.
std::string error_text(ErrorCode code, std::string_view name = {});

// "catalogue text" or "catalogue text: detail".
Error make_error(ErrorCode code, Position where, std::string_view name = {}, std::string_view detail = {});

}  // namespace gppl
