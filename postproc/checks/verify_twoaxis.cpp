// `postproc verify --dialect 2xaxiscnc`: both sides of the comparison as a 2XAxisCNC machine sees
// them. The format has X and Y only, straight moves at a speed coefficient, M03/M05 and pauses, so
// the toolpath is projected on X Y (Z-only moves vanish as zero-length moves), feeds become the
// coefficients the post writes, tool changes (a comment in the program) and spindle speeds are not
// compared. Comments, relays, pulses and scripts of the program are not motion.
#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "machines/2xaxiscnc/reader.hpp"
#include "postproc/checks/verify.hpp"
#include "toolpath/error.hpp"
#include "toolpath/value.hpp"

namespace postproc::verify {
namespace {

using toolpath::Command;

double number_or(const Command& c, std::string_view name, double fallback) {
  const toolpath::Value* v = c.find(name);
  return v ? v->as_number() : fallback;
}

class TwoAxisNc final : public MotionSource {
public:
  TwoAxisNc(const std::filesystem::path& program, const Target& target) : target_(target) {
    twoaxis::Options options;
    options.machine_speed = target.machine_speed;
    options.rapid_coefficient = 0;  // every move is a @line with its coefficient
    reader_ = twoaxis::TwoAxisReader::open(program.string(), options);
  }

  bool next(Motion& m) override {
    while (reader_->next(command_)) {
      if (convert(command_, m)) return true;
    }
    if (reader_->error_count() > 0) {
      const auto& d = reader_->diagnostics();
      for (const auto& e : d)
        if (e.severity == twoaxis::Diagnostic::Severity::Error)
          throw toolpath::InputError({e.file.empty() ? reader_->file_name() : e.file, e.line, e.column}, e.message);
    }
    return false;
  }

private:
  bool convert(const Command& c, Motion& m) {
    m = Motion{};
    m.name = c.name;
    m.where = reader_->line();
    if (c.name == "@line" || c.name == "@rapid_move") {
      m.kind = MotionKind::Feed;
      // X0Y0 runs at full machine speed
      const double k = c.find("goto_zero") ? 1.0 : number_or(c, "speed_coef", 1.0);
      m.feed = k * target_.machine_speed;
      m.from = position_;
      m.from_known = true;
      m.to = Eigen::Vector3d(number_or(c, "xpos", 0.0), number_or(c, "ypos", 0.0), 0.0);
      position_ = m.to;
      return true;
    }
    if (c.name == "@home") {  // homing: the origin again, no motion to compare
      if (c.find("xpos")) position_ = Eigen::Vector3d::Zero();
      return false;
    }
    if (c.name == "@start_tool" || c.name == "@stop_tool") {
      m.kind = MotionKind::Spindle;
      m.spindle = c.name == "@start_tool" ? 1 : 0;
      return true;
    }
    if (c.name == "@delay") {
      m.kind = MotionKind::Dwell;
      m.seconds = number_or(c, "delay_period", 0.0);
      return true;
    }
    if (c.name == "@a_move") {
      m.kind = MotionKind::Other;
      return true;
    }
    return false;
  }

  Target target_;
  std::unique_ptr<twoaxis::TwoAxisReader> reader_;
  Command command_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();  // a program starts at X0 Y0
};

class TwoAxisExpected final : public MotionSource {
public:
  TwoAxisExpected(MotionSource& source, const Target& target) : source_(source), target_(target) {}

  bool next(Motion& m) override {
    while (source_.next(m)) {
      switch (m.kind) {
        case MotionKind::Rapid:
        case MotionKind::Feed:
        case MotionKind::Arc: {
          const bool arc = m.kind == MotionKind::Arc;
          double k = target_.rapid_coefficient;
          if (m.kind != MotionKind::Rapid) {
            k = std::round(m.feed / target_.machine_speed * 1e4) / 1e4;  // as the post rounds it
            k = std::clamp(k, 0.0001, 1.0);
          }
          m.kind = arc ? MotionKind::Arc : MotionKind::Feed;
          m.feed = k * target_.machine_speed;
          // An axis the toolpath has not given yet is where the program starts it: 0.
          Eigen::Vector3d to(m.known[0] ? m.to.x() : position_.x(), m.known[1] ? m.to.y() : position_.y(), 0.0);
          m.from = position_;
          m.from_known = true;
          m.to = to;
          m.known = {true, true, true};
          position_ = to;
          return true;
        }
        case MotionKind::Tool: continue;  // only a comment in the program
        case MotionKind::Spindle:
          m.spindle = m.spindle != 0 ? 1 : 0;  // M03 is the only direction, no speed
          m.speed = 0.0;
          return true;
        case MotionKind::Dwell:
        case MotionKind::Other: return true;
      }
    }
    return false;
  }

private:
  MotionSource& source_;
  Target target_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
};

}  // namespace

std::unique_ptr<MotionSource> twoaxis_nc_motion(const std::filesystem::path& program, const Target& target) {
  return std::make_unique<TwoAxisNc>(program, target);
}

std::unique_ptr<MotionSource> twoaxis_expected(MotionSource& source, const Target& target) {
  return std::make_unique<TwoAxisExpected>(source, target);
}

}  // namespace postproc::verify
