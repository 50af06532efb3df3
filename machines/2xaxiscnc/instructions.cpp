// The one-command frames of a 2XAxisCNC program: comments and instructions (docs/2xaxiscnc.md).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "machines/2xaxiscnc/numbers.hpp"
#include "machines/2xaxiscnc/reader.hpp"
#include "toolpath/bounded_read.hpp"

namespace twoaxis {

using toolpath::Command;
using toolpath::ParamKey;
using toolpath::Value;

namespace {

bool is_artcam_import(std::string_view text) {
  // `ArtCam_Import` in Cyrillic, UTF-8 or the Windows code page: written by the application in
  // place of the ArtCAM marker of a program it has converted.
  return text == "ArtCam_\xD0\x98\xD0\xBC\xD0\xBF\xD0\xBE\xD1\x80\xD1\x82" || text == "ArtCam_\xC8\xEC\xEF\xEE\xF0\xF2";
}

}  // namespace

void TwoAxisReader::instruction(std::string_view text, std::size_t column, Command& out, bool& produced) {
  const Classified c = classify(text);
  if (c.kind == Instruction::Unknown) {
    diagnose(toolpath::Severity::Error, column,
             fmt::format("unknown instruction `{}`: expected a (comment), XHYH, X0Y0, SpEn, M03, M05, Out1..Out4, "
                         "P<seconds>, Imp_<pin>_<interval>_<count>, A<mm>, AH or RunScript_<name>.script", toolpath::excerpt(text)));
    return;
  }
  if (c.case_differs)
    diagnose(toolpath::Severity::Warning, column, fmt::format("`{}` is written in another case than the format's", toolpath::excerpt(text)));
  const std::size_t arg_column = column + c.argument_offset;
  out.clear();
  auto spindle = [&](bool on, std::string_view source) {
    spindle_ = on;
    out.name = on ? "@start_tool" : "@stop_tool";
    if (on) out.set(ParamKey::spin_direction, Value::make_enum("CW"));
    out.set("source", Value::make_string(std::string(source)));
  };
  switch (c.kind) {
    case Instruction::Comment:
      if (is_artcam_import(c.argument)) {
        out.name = "@marker";
        out.set("kind", Value::make_string("ArtCam_import"));
        out.set("converted", Value::make_logical(false));
        break;
      }
      out.name = "@message";
      out.set(ParamKey::message, Value::make_string(std::string(c.argument)));
      break;
    case Instruction::G91Marker:
      out.name = "@marker";
      out.set("kind", Value::make_string("G91"));
      out.set("converted", Value::make_logical(false));
      break;
    case Instruction::ArtCamMarker:
    case Instruction::G90Marker:
      diagnose(toolpath::Severity::Error, column,
               fmt::format("`{}` converts absolute coordinates only in the first frame of a program: ignored", toolpath::excerpt(text)));
      return;
    case Instruction::HomeXY:
    case Instruction::GotoZero: {
      const bool home = c.kind == Instruction::HomeXY;
      if (options_.machine_speed > 0 && !home) motion_minutes_ += std::hypot(x_, y_) / options_.machine_speed;
      if (!home) path_length_ += std::hypot(x_, y_);
      x_ = y_ = 0;
      abs_x_ = abs_y_ = 0;
      out.name = home ? "@home" : "@rapid_move";
      if (home) out.set("axes", Value::make_string("XY"));
      out.set(ParamKey::xpos, Value::make_numeric(0));
      out.set(ParamKey::ypos, Value::make_numeric(0));
      if (!home) out.set("goto_zero", Value::make_logical(true));
      break;
    }
    case Instruction::HomeA:
      a_ = 0;
      out.name = "@home";
      out.set("axes", Value::make_string("A"));
      out.set(ParamKey::apos, Value::make_numeric(0));
      break;
    case Instruction::SpindleOn: spindle(true, "M03"); break;
    case Instruction::SpindleOff: spindle(false, "M05"); break;
    case Instruction::SpindleToggle: spindle(!spindle_, "SpEn"); break;
    case Instruction::Relay: {
      const int n = c.argument[0] - '0';
      relays_[static_cast<std::size_t>(n - 1)] = !relays_[static_cast<std::size_t>(n - 1)];
      out.name = "@relay";
      out.set("relay", Value::make_integer(n));
      out.set("state", Value::make_logical(relays_[static_cast<std::size_t>(n - 1)]));
      break;
    }
    case Instruction::Pause: {
      double s = 0;
      if (!read_number(c.argument, arg_column, s)) return;
      if (s < 0) {
        diagnose(toolpath::Severity::Error, arg_column, fmt::format("negative pause `{}`: expected seconds >= 0", toolpath::excerpt(text)));
        return;
      }
      if (options_.single_precision) s = as_single(s);
      pause_seconds_ += s;
      out.name = "@delay";
      out.set(ParamKey::delay_period, Value::make_numeric(tidy(s)));
      break;
    }
    case Instruction::AMove: {
      double d = 0;
      if (!read_number(c.argument, arg_column, d)) return;
      if (options_.single_precision) d = as_single(d);
      a_ += d;
      out.name = "@a_move";
      out.set(ParamKey::apos, Value::make_numeric(tidy(a_)));
      out.set("delta", Value::make_numeric(tidy(d)));
      break;
    }
    case Instruction::Pulses: {
      // pin_interval_count: three numbers separated by `_`
      std::string_view parts[3];
      std::size_t offsets[3] = {};
      std::string_view rest = c.argument;
      std::size_t at = 0, n = 0;
      for (; n < 3; ++n) {
        const std::size_t cut = n < 2 ? rest.find('_') : rest.size();
        if (cut == std::string_view::npos || (n == 2 && rest.find('_') != std::string_view::npos)) break;
        parts[n] = rest.substr(0, cut);
        offsets[n] = at;
        rest = cut < rest.size() ? rest.substr(cut + 1) : std::string_view();
        at += cut + 1;
      }
      if (n != 3) {
        diagnose(toolpath::Severity::Error, column,
                 fmt::format("malformed pulse instruction `{}`: expected Imp_<pin>_<interval>_<count>", toolpath::excerpt(text)));
        return;
      }
      double v[3];
      for (std::size_t i = 0; i < 3; ++i)
        if (!read_number(parts[i], arg_column + offsets[i], v[i])) return;
      // Bounded before the integer conversions (a pin of 25 digits was an undefined cast, found by
      // fuzzing): an LPT port has 25 pins; a billion pulses is far beyond any real program.
      if (v[0] < 1 || v[0] > 25 || v[0] != std::floor(v[0]) || v[2] < 0 || v[2] > 1e9 || v[2] != std::floor(v[2]) ||
          v[1] < 0) {
        diagnose(toolpath::Severity::Error, arg_column,
                 fmt::format("pulse instruction `{}`: the pin must be whole in 1..25, the count whole in 0..1e9, the "
                             "interval not negative", toolpath::excerpt(text)));
        return;
      }
      pause_seconds_ += v[1] * v[2];
      out.name = "@pulses";
      out.set("pin", Value::make_integer(static_cast<std::int64_t>(v[0])));
      out.set("interval", Value::make_numeric(tidy(v[1])));
      out.set("count", Value::make_integer(static_cast<std::int64_t>(v[2])));
      out.set("duration", Value::make_numeric(tidy(v[1] * v[2])));
      break;
    }
    case Instruction::Script:
      if (!options_.scripts_folder.empty()) return run_script(c.argument, column, out, produced);
      diagnose(toolpath::Severity::Warning, column,
               fmt::format("script `{}` is not read (no scripts folder): taken as making no motion", toolpath::excerpt(c.argument)));
      out.name = "@script_call";
      out.set("name", Value::make_string(std::string(c.argument)));
      out.set("inlined", Value::make_logical(false));
      break;
    case Instruction::Unknown: return;
  }
  produced = true;
}

// The script's frames run next, in the same machine state; its commands carry `script`.
void TwoAxisReader::run_script(std::string_view name, std::size_t column, Command& out, bool& produced) {
  const std::string file = (std::filesystem::path(options_.scripts_folder) / std::string(name)).string();
  for (const Input& i : inputs_)
    if (i.script == file) {
      diagnose(toolpath::Severity::Error, column, fmt::format("script `{}` runs itself: skipped", toolpath::excerpt(name)));
      return;
    }
  if (inputs_.size() > kMaxScriptDepth) {
    diagnose(toolpath::Severity::Error, column, fmt::format("scripts nest deeper than {}: `{}` skipped", kMaxScriptDepth, toolpath::excerpt(name)));
    return;
  }
  auto stream = std::make_unique<std::ifstream>(file, std::ios::binary);
  if (!*stream) {
    diagnose(toolpath::Severity::Error, column, fmt::format("cannot open script `{}`: skipped", toolpath::excerpt(file, 200)));
    return;
  }
  out.name = "@script_call";
  out.set("name", Value::make_string(std::string(name)));
  out.set("inlined", Value::make_logical(true));
  out.set("file", Value::make_string(file));
  produced = true;
  Input input;
  input.in = stream.get();
  input.owned = std::move(stream);
  input.script = file;
  inputs_.push_back(std::move(input));
}

}  // namespace twoaxis
