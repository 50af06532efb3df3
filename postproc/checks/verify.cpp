// `postproc verify`: the NC side (a controller model's motion), normalisation and comparison.
#include "postproc/checks/verify.hpp"

#include <cmath>
#include <deque>
#include <numbers>

#include <Eigen/Geometry>  // cross(): declared in Core, defined here (Release builds fail to link without it)
#include <fmt/format.h>

#include "toolpath/value.hpp"

namespace postproc::verify {
namespace {

using toolpath::Command;
using toolpath::iequals;
namespace geo = toolpath::geometry;

double number_or(const Command& c, std::string_view name, double fallback) {
  const toolpath::Value* v = c.find(name);
  return v ? v->as_number() : fallback;
}

std::string word(const Command& c, std::string_view name) {
  const toolpath::Value* v = c.find(name);
  return v ? v->text : std::string();
}

class NcMotion final : public MotionSource {
public:
  NcMotion(std::unique_ptr<machines::ProgramSource> reader, const machines::VerifyProfile& profile,
           std::function<void(const Command&, std::size_t)> observe)
      : reader_(std::move(reader)), profile_(profile), observe_(std::move(observe)) {
    started_ = profile.planar_speeds;  // a planar program starts at its origin, X0 Y0
  }

  bool next(Motion& out) override {
    while (reader_->next(command_)) {
      if (observe_) observe_(command_, reader_->line());
      if (convert(command_, out)) return true;
    }
    return false;
  }

private:
  bool convert(const Command& c, Motion& m) {
    m = Motion{};
    m.name = c.name;
    m.where = reader_->line();
    const Eigen::Vector3d to(number_or(c, "xpos", position_.x()), number_or(c, "ypos", position_.y()),
                             number_or(c, "zpos", position_.z()));
    if (iequals(c.name, "@rapid_move") || iequals(c.name, "@line")) {
      m.kind = iequals(c.name, "@line") ? MotionKind::Feed : MotionKind::Rapid;
      m.feed = m.kind == MotionKind::Feed ? number_or(c, "feed", 0.0) : 0.0;
      if (profile_.planar_speeds && m.kind == MotionKind::Rapid) {  // back to X0 Y0: at full machine speed
        m.kind = MotionKind::Feed;
        m.feed = profile_.machine_speed;
      }
      return moved(m, to);
    }
    if (iequals(c.name, "@home")) {  // homing sets the origin again: no motion to compare
      if (c.find("xpos")) position_ = Eigen::Vector3d::Zero();
      return false;
    }
    if (iequals(c.name, "@arc")) {
      m.kind = MotionKind::Arc;
      m.feed = number_or(c, "feed", 0.0);
      auto plane = geo::parse_plane(word(c, "arc_plane")).value_or(geo::Plane::XY);
      Eigen::Vector3d centre(number_or(c, "xcenter", 0.0), number_or(c, "ycenter", 0.0), number_or(c, "zcenter", 0.0));
      auto dir = iequals(word(c, "arc_direction"), "CW") ? geo::Direction::CW : geo::Direction::CCW;
      m.arc = geo::make_arc(position_, to, centre, plane, dir, number_or(c, "arc_size", 0.0));
      return moved(m, to);
    }
    if (iequals(c.name, "@delay")) {
      m.kind = MotionKind::Dwell;
      m.seconds = number_or(c, "delay_period", 0.0);
      return true;
    }
    if (iequals(c.name, "@change_tool")) {
      m.kind = MotionKind::Tool;
      m.tool = static_cast<std::int64_t>(number_or(c, "tool_number", 0));
      return true;
    }
    if (iequals(c.name, "@start_tool") || iequals(c.name, "@stop_tool")) {
      m.kind = MotionKind::Spindle;
      spindle_ = iequals(c.name, "@stop_tool") ? 0 : iequals(word(c, "spin_direction"), "CCW") ? -1 : 1;
      m.spindle = spindle_;
      m.speed = spindle_ ? number_or(c, "spin", 0.0) : 0.0;
      return true;
    }
    if (iequals(c.name, "@m_feed_spin")) {
      if (spindle_ == 0 || !c.find("spin")) return false;
      m.kind = MotionKind::Spindle;
      m.spindle = spindle_;
      m.speed = number_or(c, "spin", 0.0);
      return true;
    }
    if (iequals(c.name, "@thread_move") || iequals(c.name, "@macro") || iequals(c.name, "@probe") ||
        iequals(c.name, "@a_move")) {
      m.kind = MotionKind::Other;
      return true;
    }
    return false;  // messages, coolant, program frame: not compared
  }

  bool moved(Motion& m, const Eigen::Vector3d& to) {
    // The model starts at X0 Y0 Z0: a first move to there is no move (the toolpath side drops the
    // same one), whatever the program's first words (`G0 Z0`, `G0 X0. Y0.`).
    if (!started_ && m.kind != MotionKind::Arc && (to - position_).norm() <= 1e-9) return false;
    m.from = position_;
    m.from_known = started_;
    m.to = to;
    position_ = to;
    started_ = true;
    return true;
  }

  std::unique_ptr<machines::ProgramSource> reader_;
  machines::VerifyProfile profile_;
  std::function<void(const Command&, std::size_t)> observe_;
  Command command_;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  bool started_ = false;  // the first move's start is the controller's, not the program's
  int spindle_ = 0;
};

bool all_known(const Motion& m) { return m.known[0] && m.known[1] && m.known[2]; }

bool straight(const Motion& m) { return m.kind == MotionKind::Rapid || m.kind == MotionKind::Feed; }

class Normalised final : public MotionSource {
public:
  Normalised(MotionSource& source, const Tolerances& tolerances) : source_(source), tol_(tolerances) {}

  bool next(Motion& out) override {
    for (;;) {
      Motion m;
      if (!source_.next(m)) break;
      if (!keep(m)) continue;
      if (held_ && joins(*held_, m)) {
        held_->to = m.to;
        continue;
      }
      if (held_) {
        out = std::move(*held_);
        held_ = std::move(m);
        return true;
      }
      held_ = std::move(m);
    }
    if (!held_) return false;
    out = std::move(*held_);
    held_.reset();
    return true;
  }

private:
  bool keep(const Motion& m) {
    if (m.kind == MotionKind::Spindle) {
      bool same = m.spindle == spindle_ && (m.spindle == 0 || std::abs(m.speed - speed_) <= tol_.feed);
      spindle_ = m.spindle;
      speed_ = m.speed;
      return !same;
    }
    if (straight(m) && m.from_known && all_known(m) && (m.to - m.from).norm() <= tol_.position) return false;
    return true;
  }

  // Two straight moves of one kind and feed, the second going on in the first one's direction.
  static bool joins(const Motion& a, const Motion& b) {
    if (a.optional != b.optional || a.approach) return false;  // compare() joins them when the program did
    if (!straight(a) || a.kind != b.kind || std::abs(a.feed - b.feed) > 1e-9) return false;
    if (!a.from_known || !b.from_known || !all_known(a) || !all_known(b)) return false;
    const Eigen::Vector3d u = a.to - a.from, v = b.to - b.from;
    if (u.norm() < 1e-12 || v.norm() < 1e-12 || u.dot(v) <= 0) return false;
    return u.cross(v).norm() / u.norm() <= 1e-6;  // distance of b's end from a's line, per unit of v
  }

  MotionSource& source_;
  Tolerances tol_;
  std::optional<Motion> held_;
  int spindle_ = 0;
  double speed_ = 0.0;
};

std::string_view kind_name(MotionKind k) {
  switch (k) {
    case MotionKind::Rapid: return "rapid";
    case MotionKind::Feed: return "feed";
    case MotionKind::Arc: return "arc";
    case MotionKind::Dwell: return "dwell";
    case MotionKind::Tool: return "tool change";
    case MotionKind::Spindle: return "spindle";
    case MotionKind::Other: return "other";
  }
  return "?";
}

std::string point_text(const Eigen::Vector3d& p, const std::array<bool, 3>& known) {
  std::string s;
  const char* axis = "XYZ";
  for (int i = 0; i < 3; ++i)
    s += known[i] ? fmt::format("{}{}{:.4f}", i ? " " : "", axis[i], p[i]) : fmt::format("{}{}?", i ? " " : "", axis[i]);
  return s;
}

// The first way `a` (expected) and `b` (actual) differ, or empty.
std::string difference(const Motion& a, const Motion& b, const Tolerances& given) {
  Tolerances t = given;  // a difference of exactly the tolerance passes, whatever the binary noise
  t.position += 1e-9;
  t.feed += 1e-9;
  t.seconds += 1e-9;
  if (a.kind != b.kind) return fmt::format("expected a {}, the NC program makes a {}", kind_name(a.kind), kind_name(b.kind));
  switch (a.kind) {
    case MotionKind::Rapid:
    case MotionKind::Feed:
    case MotionKind::Arc: {
      for (int i = 0; i < 3; ++i)
        if (a.known[i] && std::abs(a.to[i] - b.to[i]) > t.position)
          return fmt::format("end point differs in {} by {:.4f} mm", "XYZ"[i], b.to[i] - a.to[i]);
      if (a.kind != MotionKind::Rapid && std::abs(a.feed - b.feed) > t.feed)
        return fmt::format("feed {} instead of {}", b.feed, a.feed);
      if (a.kind != MotionKind::Arc) return {};
      if (a.arc.plane != b.arc.plane)
        return fmt::format("arc in plane {} instead of {}", geo::plane_name(b.arc.plane), geo::plane_name(a.arc.plane));
      if (a.arc.direction != b.arc.direction) return "arc turns the other way";
      if ((a.arc.centre - b.arc.centre).norm() > t.position)
        return fmt::format("arc centre differs by {:.4f} mm", (a.arc.centre - b.arc.centre).norm());
      if (std::abs(a.arc.radius - b.arc.radius) > t.position)
        return fmt::format("arc radius {:.4f} instead of {:.4f}", b.arc.radius, a.arc.radius);
      const double length = std::abs(a.arc.sweep - b.arc.sweep) * std::numbers::pi / 180.0 * a.arc.radius;
      if (length > t.position) return fmt::format("arc sweeps {:.4f} degrees instead of {:.4f}", b.arc.sweep, a.arc.sweep);
      return {};
    }
    case MotionKind::Dwell:
      if (std::abs(a.seconds - b.seconds) > t.seconds) return fmt::format("dwell {} s instead of {} s", b.seconds, a.seconds);
      return {};
    case MotionKind::Tool:
      if (a.tool != b.tool) return fmt::format("tool {} instead of {}", b.tool, a.tool);
      return {};
    case MotionKind::Spindle:
      if (a.spindle != b.spindle || (a.spindle && std::abs(a.speed - b.speed) > t.feed))
        return fmt::format("spindle {} instead of {}", describe(b), describe(a));
      return {};
    case MotionKind::Other:
      return "an event verify does not compare";
  }
  return {};
}

}  // namespace

std::unique_ptr<MotionSource> nc_motion(const std::filesystem::path& program, const machines::Controller& controller,
                                        std::string_view dialect, const machines::ReadOptions& options,
                                        std::ostream& warnings,
                                        std::function<void(const Command&, std::size_t)> observe) {
  machines::ReadOptions read = options;
  read.for_verify = true;
  return std::make_unique<NcMotion>(controller.open(program.string(), dialect, read, warnings),
                                    controller.verify_profile(read), std::move(observe));
}

namespace {

std::string duration(double seconds) {
  const auto whole = static_cast<long long>(std::llround(seconds));
  if (whole < 60) return fmt::format("{} s", whole);
  if (whole < 3600) return fmt::format("{} min {} s", whole / 60, whole % 60);
  return fmt::format("{} h {} min {} s", whole / 3600, whole % 3600 / 60, whole % 60);
}

}  // namespace

std::string describe(const CycleTime& time) {
  std::string s = duration(time.seconds);
  std::string tools;
  for (const auto& t : time.tools) {
    if (time.tools.size() == 1) break;               // no tool change: no breakdown
    if (t.number == 0 && t.seconds < 0.5) continue;  // nothing before the first tool change
    if (!tools.empty()) tools += ", ";
    tools += t.number == 0 ? fmt::format("before the first tool {}", duration(t.seconds))
                           : fmt::format("T{} {}", t.number, duration(t.seconds));
  }
  if (!tools.empty()) s += " (" + tools + ")";
  if (time.rapid_feed_missing) s += "; rapids not timed: the machine file has no rapid_feed";
  return s;
}

std::unique_ptr<MotionSource> normalised(MotionSource& source, const Tolerances& tolerances) {
  return std::make_unique<Normalised>(source, tolerances);
}

Result compare(MotionSource& expected, MotionSource& actual, const Tolerances& tolerances) {
  Result result;
  std::optional<Motion> next_a;  // read ahead on the expected side
  auto pull = [&](Motion& m) {
    if (!next_a) return expected.next(m);
    m = std::move(*next_a);
    next_a.reset();
    return true;
  };
  Motion a, b;
  bool has_a = pull(a), has_b = actual.next(b);
  for (;;) {
    if (!has_a && !has_b) return result;
    const std::size_t ordinal = result.compared + 1;
    if (!has_b) {
      if (a.optional) {  // the program leaves the end move out
        has_a = pull(a);
        continue;
      }
      result.divergence = Divergence{ordinal, "the NC program ends here; the toolpath goes on", a, std::nullopt};
      return result;
    }
    // A dwell the program adds (to let the spindle reach its speed, `M3 G4 P1`) moves nothing: passed over.
    if (b.kind == MotionKind::Dwell && (!has_a || a.kind != MotionKind::Dwell)) {
      has_b = actual.next(b);
      continue;
    }
    if (!has_a) {
      result.divergence = Divergence{ordinal, "the NC program goes on after the toolpath ends", std::nullopt, b};
      return result;
    }
    // A retract straight up before a tool change (to the tool-change height) is the program's to make.
    if (b.kind == MotionKind::Rapid && (a.kind == MotionKind::Tool || (a.kind == MotionKind::Spindle && a.spindle == 0)) &&
        std::abs(b.to.x() - b.from.x()) <= tolerances.position && std::abs(b.to.y() - b.from.y()) <= tolerances.position &&
        b.to.z() > b.from.z()) {
      has_b = actual.next(b);
      continue;
    }
    std::string what = difference(a, b, tolerances);
    // The program may make two moves in one block: a retract and the optional end height, or a tool
    // change's approach in X Y and the move down.
    if ((!what.empty() || a.approach) && (!a.optional || a.approach) && straight(a)) {  // an approach: the join first
      Motion ahead;
      if (!next_a && expected.next(ahead)) next_a = std::move(ahead);
      if (next_a && (next_a->optional || a.approach) && next_a->kind == a.kind &&
          std::abs(next_a->feed - a.feed) <= 1e-9) {
        Motion joined = a;
        joined.to = next_a->to;
        joined.known = next_a->known;
        if (difference(joined, b, tolerances).empty()) {
          next_a.reset();
          what.clear();
        }
      }
    }
    if (!what.empty() && a.optional) {  // not made here: the next expected event against the same one
      has_a = pull(a);
      continue;
    }
    if (!what.empty()) {
      result.divergence = Divergence{ordinal, what, a, b};
      return result;
    }
    ++result.compared;
    has_a = pull(a);
    has_b = actual.next(b);
  }
}

std::string describe(const Motion& m) {
  switch (m.kind) {
    case MotionKind::Rapid: return "rapid to " + point_text(m.to, m.known);
    case MotionKind::Feed: return fmt::format("feed to {} F{}", point_text(m.to, m.known), m.feed);
    case MotionKind::Arc:
      return fmt::format("arc {} {} to {} centre {} R{:.4f} sweep {:.4f} F{}", m.arc.direction == geo::Direction::CW ? "CW" : "CCW",
                         geo::plane_name(m.arc.plane), point_text(m.to, m.known), point_text(m.arc.centre, {true, true, true}),
                         m.arc.radius, m.arc.sweep, m.feed);
    case MotionKind::Dwell: return fmt::format("dwell {} s", m.seconds);
    case MotionKind::Tool: return fmt::format("tool change T{}", m.tool);
    case MotionKind::Spindle:
      return m.spindle == 0 ? std::string("spindle off") : fmt::format("spindle {} S{}", m.spindle > 0 ? "CW" : "CCW", m.speed);
    case MotionKind::Other: return m.name;
  }
  return "?";
}

}  // namespace postproc::verify
