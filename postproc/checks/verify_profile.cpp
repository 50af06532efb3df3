// The toolpath side of `postproc verify` as the controller's programs can say it (VerifyProfile).
// A controller whose programs move in X and Y only, every move a straight line at a speed coefficient
// (planar_speeds: 2XAxisCNC): the toolpath is projected on X Y (Z-only moves vanish as zero-length
// moves), feeds become the coefficients the post writes, tool changes (a comment in such a program)
// and spindle speeds are not compared. A controller without a tool changer (GRBL): tool changes are
// the operator's, not compared. The NC side is the model's own stream (verify.cpp).
#include <algorithm>
#include <cmath>

#include "postproc/checks/verify.hpp"

namespace postproc::verify {
namespace {

class PlanarExpected final : public MotionSource {
public:
  PlanarExpected(MotionSource& source, const machines::VerifyProfile& profile) : source_(source), target_(profile) {}

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
  machines::VerifyProfile target_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
};

class WithoutToolChanges final : public MotionSource {
public:
  explicit WithoutToolChanges(MotionSource& source) : source_(source) {}
  bool next(Motion& m) override {
    while (source_.next(m))
      if (m.kind != MotionKind::Tool) return true;
    return false;
  }

private:
  MotionSource& source_;
};

class AsIs final : public MotionSource {
public:
  explicit AsIs(MotionSource& source) : source_(source) {}
  bool next(Motion& m) override { return source_.next(m); }

private:
  MotionSource& source_;
};

}  // namespace

std::unique_ptr<MotionSource> as_programmed(MotionSource& source, const machines::VerifyProfile& profile) {
  if (profile.planar_speeds) return std::make_unique<PlanarExpected>(source, profile);
  if (!profile.tool_changes) return std::make_unique<WithoutToolChanges>(source);
  return std::make_unique<AsIs>(source);
}

}  // namespace postproc::verify
