// Spec 3.3 (Write), 3.4 (GetX..), 4 (SetBulge, SetMove, SetMoveR, SetAngle).
#include "machines/pikocnc/script/gcode_builder.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "machines/pikocnc/script/ops.hpp"

namespace pikocnc::script {

namespace {

constexpr char kLetters[] = "XYZAIJRPQFSMT";

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

GcodeBuilder::GcodeBuilder(std::ostream& out, bool crlf) : out_(out), eol_(crlf ? "\r\n" : "\n") {
  buf_ += '%';
  buf_ += eol_;
  lines_ = 1;
}

void GcodeBuilder::set(Word word, double value) {
  values_[int(word)] = value;
  set_[int(word)] = true;
}

void GcodeBuilder::set_g(int g) {
  g_ = g;
  g_fresh_ = true;
}

double GcodeBuilder::last(Word axis) const { return last_[int(axis)]; }

std::optional<double> GcodeBuilder::pending(Word word) const {
  if (!set_[int(word)]) return std::nullopt;
  return values_[int(word)];
}

// Rounded half away from zero to 4 decimals, trailing zeros dropped; X..Q keep one decimal
// digit, F and S do not (spec 3.3 "Number formatting").
void GcodeBuilder::append_number(double v, bool force_decimal) {
  const double scaled = v * 10000.0;
  if (std::fabs(scaled) < 9e15) {
    const long long n = std::llround(scaled);
    if (n < 0) buf_ += '-';
    const unsigned long long a = n < 0 ? 0ULL - static_cast<unsigned long long>(n) : static_cast<unsigned long long>(n);
    fmt::format_to(std::back_inserter(buf_), "{}", a / 10000);
    unsigned frac = unsigned(a % 10000);
    if (frac == 0) {
      if (force_decimal) buf_ += ".0";
      return;
    }
    int digits = 4;
    while (frac % 10 == 0) frac /= 10, --digits;
    fmt::format_to(std::back_inserter(buf_), ".{:0{}}", frac, digits);
    return;
  }
  std::string s = fmt::format("{:.4f}", v);  // huge values: no rounding concerns at this size
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') {
    if (force_decimal) s += '0';
    else s.pop_back();
  }
  buf_ += s;
}

void GcodeBuilder::write() {
  const std::size_t start = buf_.size();
  bool has_axis = false;
  for (Word w : {Word::X, Word::Y, Word::Z, Word::A, Word::I, Word::J, Word::R}) has_axis |= set_[int(w)];
  auto space = [&] {
    if (buf_.size() > start) buf_ += ' ';
  };
  if (g_ && (g_fresh_ || has_axis)) fmt::format_to(std::back_inserter(buf_), "G{}", *g_);
  for (int w = 0; w < int(Word::Count); ++w) {
    if (!set_[w]) continue;
    space();
    buf_ += kLetters[w];
    if (Word(w) == Word::M || Word(w) == Word::T) fmt::format_to(std::back_inserter(buf_), "{}", std::int64_t(values_[w]));
    else append_number(values_[w], Word(w) != Word::F && Word(w) != Word::S);
  }
  if (comment_) {
    space();
    buf_ += '(';
    for (char c : *comment_) buf_ += (c == '\n' || c == '\r') ? ' ' : c;
    buf_ += ')';
  }
  if (buf_.size() > start) {
    buf_ += eol_;
    ++lines_;
  }
  for (int a = 0; a < 3; ++a)
    if (set_[a]) last_[a] = values_[a];
  for (bool& s : set_) s = false;
  comment_.reset();
  g_fresh_ = false;
  if (g_ && *g_ > 3) g_.reset();  // G4, G80, G81, G90...: one line only
  if (buf_.size() >= (1u << 16)) flush();
}

void GcodeBuilder::flush() {
  out_.write(buf_.data(), std::streamsize(buf_.size()));
  buf_.clear();
}

void GcodeBuilder::bulge(double v) {
  if (!g_ || (*g_ != 2 && *g_ != 3)) throw OpError("SetBulge needs SetG(2) or SetG(3) first");
  const double sx = last_[0], sy = last_[1];
  const double ex = set_[int(Word::X)] ? values_[int(Word::X)] : sx;
  const double ey = set_[int(Word::Y)] ? values_[int(Word::Y)] : sy;
  const double c = std::hypot(ex - sx, ey - sy);
  const double h = std::fabs(v);
  if (c == 0) throw OpError("SetBulge needs the arc's end point (SetX/SetY) away from the current point");
  if (h == 0) throw OpError("SetBulge(0): a bulge of zero height is a straight line, not an arc");
  const double r = c * c / (8 * h) + h / 2;
  set(Word::R, h <= c / 2 ? r : -r);
}

void GcodeBuilder::move(double len, double degrees) {
  set(Word::X, last_[0] + len * std::cos(radians(degrees)));
  set(Word::Y, last_[1] + len * std::sin(radians(degrees)));
}

void GcodeBuilder::move_relative(double len, double degrees) {
  heading_ += degrees;
  move(len, heading_);
}

}  // namespace pikocnc::script
