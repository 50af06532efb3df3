#include "machines/2xaxiscnc/reader.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "machines/2xaxiscnc/numbers.hpp"
#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"

namespace twoaxis {

using toolpath::Command;
using toolpath::ParamKey;
using toolpath::Value;

namespace {

constexpr std::size_t kChunk = 256 * 1024;
// No program line comes near this (the trace and PikoCNC readers stop at the same length).
constexpr std::size_t kMaxLine = std::size_t{16} << 20;
constexpr double kMinCoef = 0.0001, kMaxCoef = 1.0;

Value number(double v) { return Value::make_numeric(v); }

}  // namespace

TwoAxisReader::TwoAxisReader(std::istream& in, std::string file_name, Options options)
    : file_name_(std::move(file_name)), options_(std::move(options)), diagnostics_(options_.max_diagnostics) {
  inputs_.reserve(kMaxScriptDepth + 1);  // string_views into a buffer stay valid while a script opens
  inputs_.emplace_back();
  inputs_.back().in = &in;
}

TwoAxisReader::~TwoAxisReader() = default;

std::unique_ptr<TwoAxisReader> TwoAxisReader::open(const std::string& path, Options options) {
  auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*file) throw toolpath::InputError({path, 0, 0}, "cannot open file");
  auto reader = std::make_unique<TwoAxisReader>(*file, path, std::move(options));
  reader->inputs_.front().owned = std::move(file);
  return reader;
}

std::unique_ptr<TwoAxisReader> TwoAxisReader::from_string(std::string text, std::string file_name, Options options) {
  auto stream = std::make_unique<std::istringstream>(std::move(text));
  auto reader = std::make_unique<TwoAxisReader>(*stream, std::move(file_name), std::move(options));
  reader->inputs_.front().owned = std::move(stream);
  return reader;
}

// The next line without its LF (a CR before it is a blank for split_frame). The buffer holds one
// chunk and the unfinished line at its end, so memory stays flat.
// A script that ends gives the line after its call back to its caller.
bool TwoAxisReader::next_line(std::string_view& line) {
  for (;;) {
    Input& f = inputs_.back();
    const char* base = f.buffer.data() + f.pos;
    const std::size_t left = f.buffer.size() - f.pos;
    if (const void* nl = std::memchr(base, '\n', left)) {
      const std::size_t len = static_cast<std::size_t>(static_cast<const char*>(nl) - base);
      line = std::string_view(base, len);
      f.pos += len + 1;
      ++f.line;
      return true;
    }
    if (f.eof) {
      if (left > 0) {
        line = std::string_view(base, left);  // the last line has no line end
        f.pos = f.buffer.size();
        ++f.line;
        return true;
      }
      if (inputs_.size() == 1) return false;
      inputs_.pop_back();
      continue;
    }
    if (left > kMaxLine)  // a binary file or a generator gone wrong: memory would grow without bound
      throw toolpath::InputError({f.script.empty() ? file_name_ : f.script, f.line + 1, 1},
                                 "line longer than 16 MiB: not a 2XAxisCNC program?");
    f.buffer.erase(0, f.pos);
    f.pos = 0;
    const std::size_t old = f.buffer.size();
    f.buffer.resize(old + kChunk);
    f.in->read(f.buffer.data() + old, static_cast<std::streamsize>(kChunk));
    const auto got = static_cast<std::size_t>(f.in->gcount());
    f.buffer.resize(old + got);
    if (got < kChunk) f.eof = true;
  }
}

void TwoAxisReader::diagnose(toolpath::Severity s, std::size_t column, std::string message) {
  diagnostics_.add({{inputs_.back().script, inputs_.back().line, column}, s, std::move(message)});
}

bool TwoAxisReader::read_number(std::string_view text, std::size_t column, double& value) {
  const Number n = parse_number(text);
  switch (n.status) {
    case Number::Status::Malformed:
      diagnose(toolpath::Severity::Error, column,
               fmt::format("malformed number `{}`: expected [-]digits[,digits]", toolpath::excerpt(text)));
      return false;
    case Number::Status::OutOfRange:
      diagnose(toolpath::Severity::Error, column, fmt::format("number `{}` is beyond the single-precision range", toolpath::excerpt(text)));
      return false;
    case Number::Status::NonPortable:
      diagnose(toolpath::Severity::Warning, column,
               fmt::format("non-portable number `{}`: the application expects a decimal comma and no exponent", toolpath::excerpt(text)));
      break;
    case Number::Status::Ok: break;
  }
  value = n.value;
  return true;
}

bool TwoAxisReader::next(Command& out) {
  for (;;) {
    switch (phase_) {
      case Phase::StartFile:
        out.clear();
        out.name = "@start_of_file";
        out.set(ParamKey::g_file_name, Value::make_string(file_name_));
        out.set("dialect", Value::make_string("2xaxiscnc"));
        out.set(ParamKey::inch_system, Value::make_logical(false));
        phase_ = Phase::StartProgram;
        break;
      case Phase::StartProgram:
        out.clear();
        out.name = "@start_program";
        out.set(ParamKey::xpos, number(0));
        out.set(ParamKey::ypos, number(0));
        phase_ = Phase::Frames;
        break;
      case Phase::Frames: {
        std::string_view text;
        if (!next_line(text)) {
          phase_ = Phase::EndProgram;
          continue;
        }
        // where the frame is, before a RunScript frame opens its script
        const std::size_t line = inputs_.back().line;
        const bool in_script = inputs_.size() > 1;
        if (in_script) command_script_ = inputs_.back().script;
        bool produced = false;
        frame(text, out, produced);
        if (!produced) continue;
        command_line_ = line;
        if (in_script) {
          out.set("script", Value::make_string(command_script_));
        } else {
          command_script_.clear();
        }
        out.index = index_++;
        return true;
      }
      case Phase::EndProgram:
        command_line_ = 0;
        command_script_.clear();
        end_program(out);
        phase_ = Phase::EndFile;
        break;
      case Phase::EndFile:
        out.clear();
        out.name = "@end_of_file";
        phase_ = Phase::Done;
        break;
      case Phase::Done: return false;
    }
    out.index = index_++;
    return true;
  }
}

void TwoAxisReader::frame(std::string_view text, Command& out, bool& produced) {
  const Frame f = split_frame(text);
  if (f.count == 0) return;  // an empty line is no frame
  const bool in_script = inputs_.size() > 1;
  const bool first = first_frame_ && !in_script;
  if (!in_script) first_frame_ = false;
  if (f.count > 3) {
    diagnose(toolpath::Severity::Error, f.columns[3],
             fmt::format("{} commands in a frame: expected 1 (instruction or comment), 2 (dx dy) or 3 (dx dy coefficient)",
                         f.count));
    return;
  }
  if (f.count == 1) {
    if (first) {
      const Classified c = classify(f.commands[0]);
      if (c.kind == Instruction::ArtCamMarker || c.kind == Instruction::G90Marker) {
        // Load-time conversion: the moves that follow are absolute positions.
        converting_ = true;
        out.clear();
        out.name = "@marker";
        out.set("kind", Value::make_string(c.kind == Instruction::G90Marker ? "G90" : "ArtCam"));
        out.set("converted", Value::make_logical(true));
        produced = true;
        return;
      }
    }
    instruction(f.commands[0], f.columns[0], out, produced);
    return;
  }
  move(f, out);
  produced = out.name == "@rapid_move" || out.name == "@line";
}

void TwoAxisReader::move(const Frame& f, Command& out) {
  out.name.clear();
  double v[3] = {0, 0, 0};
  for (std::size_t i = 0; i < f.count; ++i)
    if (!read_number(f.commands[i], f.columns[i], v[i])) return;  // the frame is skipped
  double dx = v[0], dy = v[1];
  if (converting_ && inputs_.size() == 1) {  // a script's moves are its own, relative
    dx = v[0] - abs_x_;
    dy = v[1] - abs_y_;
    abs_x_ = v[0];
    abs_y_ = v[1];
  }
  if (options_.single_precision) {
    dx = as_single(dx);
    dy = as_single(dy);
  }
  if (f.count == 3) {
    double k = options_.single_precision ? as_single(v[2]) : v[2];
    // 0,0001 read as a float is a little below 0.0001: compare with the bounds as the reader stores them
    const double lo = options_.single_precision ? as_single(kMinCoef) : kMinCoef;
    if (!(k >= lo && k <= kMaxCoef)) {
      const double clamped = k < lo ? lo : kMaxCoef;
      diagnose(toolpath::Severity::Error, f.columns[2],
               fmt::format("speed coefficient {} out of range 0,0001..1: clamped to {}", toolpath::excerpt(f.commands[2]),
                           clamped == kMaxCoef ? "1" : "0,0001"));
      k = clamped;
    }
    coef_ = k;
  }
  x_ += dx;
  y_ += dy;
  const double length = std::hypot(dx, dy);
  path_length_ += length;
  if (options_.machine_speed > 0) motion_minutes_ += length / (coef_ * options_.machine_speed);
  const bool rapid = options_.rapid_coefficient > 0 && std::abs(coef_ - options_.rapid_coefficient) < 1e-7;
  out.clear();
  out.name = rapid ? "@rapid_move" : "@line";
  out.set(ParamKey::xpos, number(tidy(x_)));
  out.set(ParamKey::ypos, number(tidy(y_)));
  if (options_.machine_speed > 0) out.set(ParamKey::feed, number(tidy(tidy(coef_) * options_.machine_speed)));
  out.set("speed_coef", number(tidy(coef_)));
  if (f.count == 3) out.set("coef_changed", Value::make_logical(true));
}

void TwoAxisReader::end_program(Command& out) {
  out.clear();
  out.name = "@end_program";
  out.set(ParamKey::xpos, number(tidy(x_)));
  out.set(ParamKey::ypos, number(tidy(y_)));
  out.set(ParamKey::apos, number(tidy(a_)));
  out.set("speed_coef", number(tidy(coef_)));
  out.set("spindle_on", Value::make_logical(spindle_));
  for (std::size_t i = 0; i < relays_.size(); ++i)
    out.set(fmt::format("relay{}", i + 1), Value::make_logical(relays_[i]));
  out.set("path_length", number(tidy(path_length_)));
  if (options_.machine_speed > 0) out.set("motion_time", number(tidy(motion_minutes_ * 60.0 + pause_seconds_)));
}

}  // namespace twoaxis
