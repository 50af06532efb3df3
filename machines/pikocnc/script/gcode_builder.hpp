// The G-code line builder of spec section 3 and the path helpers of section 4: words are set one
// by one, Write() turns them into one line of a PikoCNC program.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

namespace pikocnc::script {

// The words a line can hold, in the order Write prints them (after G).
enum class Word : std::uint8_t { X, Y, Z, A, I, J, R, P, Q, F, S, M, T, Count };

class GcodeBuilder {
public:
  // Starts the program with its `%` line.
  GcodeBuilder(std::ostream& out, bool crlf);

  void set(Word word, double value);  // M and T take integral values (checked by the caller)
  void set_g(int g);
  void set_comment(std::string text) { comment_ = std::move(text); }
  void write();  // spec 3.3
  double last(Word axis) const;  // GetX/GetY/GetZ
  std::optional<double> pending(Word word) const;

  // Section 4. Errors throw OpError.
  void bulge(double v);
  void move(double len, double degrees);
  void move_relative(double len, double degrees);
  void angle(double degrees) { heading_ = degrees; }

  void flush();
  std::uint64_t lines() const { return lines_; }

private:
  void append_number(double v, bool force_decimal);
  std::ostream& out_;
  const char* eol_;
  std::string buf_;
  double values_[int(Word::Count)] = {};
  bool set_[int(Word::Count)] = {};
  std::optional<int> g_;
  bool g_fresh_ = false;
  std::optional<std::string> comment_;
  double last_[3] = {0, 0, 0};
  double heading_ = 0;
  std::uint64_t lines_ = 0;
};

}  // namespace pikocnc::script
