#include "machines/ncmodel/block_text.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

namespace ncmodel {

void Cursor::skip() {
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
}

bool Cursor::at_end() {
  skip();
  return i >= text.size();
}

char Cursor::peek() {
  skip();
  return i < text.size() ? text[i] : '\0';
}

bool Cursor::eat(char c) {
  if (peek() != c) return false;
  ++i;
  return true;
}

bool Cursor::eat(std::string_view s) {
  skip();
  if (text.substr(i, s.size()) != s) return false;
  i += s.size();
  return true;
}

std::string Cursor::ident() {
  skip();
  const std::size_t b = i;
  auto start = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  auto inner = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  if (i < text.size() && start(text[i]))
    while (i < text.size() && inner(text[i])) ++i;
  return std::string(text.substr(b, i - b));
}

std::string Cursor::keyword() {
  skip();
  std::string out;
  while (i < text.size() && std::isalpha(static_cast<unsigned char>(text[i])))
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i++])));
  return out;
}

double Cursor::number() {
  skip();
  const std::size_t b = i;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  bool digits = false;
  while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) {
    digits |= text[i] != '.';
    ++i;
  }
  if (!digits) throw BlockError{b + 1, "expected a number"};
  const char* first = text.data() + b;
  const char* last = text.data() + i;
  if (*first == '+') ++first;  // from_chars takes no '+'
  double v = 0;
  const auto [end, error] = std::from_chars(first, last, v);
  if (error == std::errc::result_out_of_range || (error == std::errc{} && !std::isfinite(v)))
    throw BlockError{b + 1, "number out of range"};
  if (error != std::errc{} || end != last)
    throw BlockError{b + 1, fmt::format("malformed number `{}`", text.substr(b, i - b))};
  return v;
}

}  // namespace ncmodel
