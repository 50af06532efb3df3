#include "postproc/engine/parameter_check.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cmath>

#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"

namespace postproc {
namespace {

using toolpath::ValueKind;

// The catalogue kind of every keyed name, built once: the check costs one index per parameter.
const std::array<int, toolpath::param_key_count + 1>& kinds_by_key() {
  static const auto table = [] {
    std::array<int, toolpath::param_key_count + 1> t;
    t.fill(-1);
    for (const ParameterSpec& spec : parameter_table())
      if (const toolpath::ParamKey key = toolpath::param_key(spec.name); key != toolpath::ParamKey::none)
        t[static_cast<std::size_t>(key)] = static_cast<int>(spec.kind);
    return t;
  }();
  return table;
}

// The value as the user wrote it, near enough to find it on the line.
std::string shown(const toolpath::Value& v) {
  switch (v.kind) {
    case ValueKind::Integer: return fmt::format("{}", v.integer);
    case ValueKind::Numeric: return fmt::format("{}", v.numeric);
    case ValueKind::Logical: return v.logical ? "TRUE" : "FALSE";
    case ValueKind::String: return fmt::format("'{}'", toolpath::excerpt(v.text));  // a value may be megabytes
    case ValueKind::Enum: return toolpath::excerpt(v.text);
  }
  return {};
}

bool zero_or_one(const toolpath::Value& v) {
  const double x = v.kind == ValueKind::Integer ? double(v.integer) : v.numeric;
  return x == 0.0 || x == 1.0;
}

// Values of the right type that still make no motion: a negative feed, an arc without a radius.
// True when `p` is none of those (cheap: the check's fast path asks it for every parameter).
inline bool in_range(const toolpath::Parameter& p) {
  if (p.key != toolpath::ParamKey::feed && p.key != toolpath::ParamKey::radius) return true;
  if (p.value.kind != ValueKind::Numeric && p.value.kind != ValueKind::Integer) return true;
  const double x = p.value.kind == ValueKind::Integer ? double(p.value.integer) : p.value.numeric;
  return p.key == toolpath::ParamKey::feed ? x >= 0 : x > 0;
}

std::string value_problem(const toolpath::Command& c, const toolpath::Parameter& p) {
  if (in_range(p)) return {};
  if (p.key == toolpath::ParamKey::feed) return fmt::format("expected a feed of 0 or more, not {}", shown(p.value));
  if (toolpath::iequals(c.name, "@arc")) return fmt::format("expected an arc radius above 0, not {}", shown(p.value));
  return {};  // a radius of 0 on another command is not an arc without a radius
}

// kind_mismatch(kind, v).empty() without building a message: the per-parameter fast path (the
// messages are made only for a value that fails).
inline bool accepts(ParameterKind kind, const toolpath::Value& v) {
  switch (kind) {
    case ParameterKind::Numeric:
      return v.kind == ValueKind::Integer || v.kind == ValueKind::Logical ||
             (v.kind == ValueKind::Numeric && std::isfinite(v.numeric));
    case ParameterKind::Integer:
      return v.kind == ValueKind::Integer || v.kind == ValueKind::Logical || v.kind == ValueKind::Enum ||
             (v.kind == ValueKind::Numeric && std::fabs(v.numeric) <= 999999999.0);
    case ParameterKind::Logical:
      return v.kind == ValueKind::Logical ||
             ((v.kind == ValueKind::Integer || v.kind == ValueKind::Numeric) && zero_or_one(v));
    case ParameterKind::String: return v.kind == ValueKind::String || v.kind == ValueKind::Enum;
    case ParameterKind::Enum: return v.kind != ValueKind::String;
  }
  return true;
}

// What a motion command cannot do without. SolidCAM writes every parameter of a command into the
// trace each time (unchanged ones flagged `F`), so a motion without its end point, feed or centre
// comes from a damaged or hand-made trace.
enum Need : std::uint32_t { kX = 1, kY = 2, kZ = 4, kFeed = 8, kDirection = 16, kCentre = 32, kTool = 64 };
constexpr int kNeeds = 7;
constexpr std::string_view kNeedNames[kNeeds] = {
    "`xpos`", "`ypos`", "`zpos`", "`feed`", "`arc_direction`",
    "centre (`xcenter` and `ycenter`, or `xcenter_rel` and `ycenter_rel`)", "`tool_number`"};

struct Required {
  std::string_view command;
  std::uint32_t needs;
};
constexpr Required kRequired[] = {
    {"@rapid_move", kX | kY | kZ},
    {"@line", kX | kY | kZ | kFeed},
    {"@arc", kX | kY | kZ | kFeed | kDirection | kCentre},
    {"@drill_point", kX | kY | kZ},
    {"@change_tool", kTool},
};

int required_of(std::string_view name) {
  for (int i = 0; i < int(std::size(kRequired)); ++i)
    if (name.size() == kRequired[i].command.size() && toolpath::iequals(name, kRequired[i].command)) return i;
  return -1;
}

// The Need bit each keyed parameter stands for (the centre counts in halves, put together below).
enum Half : std::uint32_t { kXcentre = 128, kYcentre = 256, kXrel = 512, kYrel = 1024 };
const std::array<std::uint16_t, toolpath::param_key_count + 1>& need_by_key() {
  static const auto table = [] {
    std::array<std::uint16_t, toolpath::param_key_count + 1> t{};
    using K = toolpath::ParamKey;
    const std::pair<K, std::uint32_t> bits[] = {{K::xpos, kX},          {K::ypos, kY},           {K::zpos, kZ},
                                                {K::feed, kFeed},       {K::arc_direction, kDirection},
                                                {K::xcenter, kXcentre}, {K::ycenter, kYcentre},  {K::xcenter_rel, kXrel},
                                                {K::ycenter_rel, kYrel}, {K::tool_number, kTool}};
    for (auto [key, bit] : bits) t[static_cast<std::size_t>(key)] = static_cast<std::uint16_t>(bit);
    return t;
  }();
  return table;
}

std::string need_list(std::uint32_t needs) {
  std::string list;
  int left = std::popcount(needs);
  for (int b = 0; b < kNeeds; ++b) {
    if (!(needs & (1u << b))) continue;
    --left;
    list += fmt::format("{}{}", list.empty() ? "" : left == 0 ? " and " : ", ", b == 5 ? "a centre" : kNeedNames[b]);
  }
  return list;
}

}  // namespace

std::string kind_mismatch(ParameterKind kind, const toolpath::Value& v) {
  // Each case accepts what the post variable takes without error or invented meaning (an unknown
  // word would become an enumeration code in a number).
  switch (kind) {
    case ParameterKind::Numeric:
      if (v.kind == ValueKind::Numeric && !std::isfinite(v.numeric)) return fmt::format("expected a finite number, not {}", shown(v));
      if (v.kind == ValueKind::Integer || v.kind == ValueKind::Numeric || v.kind == ValueKind::Logical) return {};
      return fmt::format("expected a number, not {}", shown(v));
    case ParameterKind::Integer:
      if (v.kind == ValueKind::Numeric && !(std::fabs(v.numeric) <= 999999999.0))
        return fmt::format("expected an integer of at most 999999999, not {}", shown(v));
      if (v.kind != ValueKind::String) return {};
      return fmt::format("expected an integer, not {}", shown(v));
    case ParameterKind::Logical:
      if (v.kind == ValueKind::Logical) return {};
      if ((v.kind == ValueKind::Integer || v.kind == ValueKind::Numeric) && zero_or_one(v)) return {};
      return fmt::format("expected TRUE, FALSE, 0 or 1, not {}", shown(v));
    case ParameterKind::String:
      if (v.kind == ValueKind::String || v.kind == ValueKind::Enum) return {};
      return fmt::format("expected a string ('text'), not {}", shown(v));
    case ParameterKind::Enum:
      if (v.kind != ValueKind::String) return {};
      return fmt::format("expected an enumeration word (such as CW or COMP_LEFT), not {}", shown(v));
  }
  return {};
}

ParameterCheck::ParameterCheck(toolpath::CommandSource& inner, std::string file_name, Warn warn)
    : inner_(inner), file_(std::move(file_name)), warn_(std::move(warn)) {}

int ParameterCheck::unkeyed_kind(const toolpath::Parameter& p) {
  auto it = unkeyed_.find(p.name);
  if (it == unkeyed_.end()) {
    if (unkeyed_.size() > 4096) unkeyed_.clear();  // a stream of ever new names: keep memory flat
    const ParameterSpec* spec = find_parameter(p.name);
    it = unkeyed_.emplace(p.name, spec ? static_cast<int>(spec->kind) : -1).first;
  }
  return it->second;
}

bool ParameterCheck::next(toolpath::Command& out) {
  if (!inner_.next(out)) return false;
  if (!out.is_stream_command()) return true;  // what the original post did itself: kept as written
  const auto& by_key = kinds_by_key();
  const auto& needs = need_by_key();
  std::uint32_t present = 0;
  for (const toolpath::Parameter& p : out.parameters) {
    const auto k = static_cast<std::size_t>(p.key);
    present |= needs[k];
    const int kind = p.key != toolpath::ParamKey::none ? by_key[k] : unkeyed_kind(p);
    if (kind < 0) continue;
    if (accepts(static_cast<ParameterKind>(kind), p.value) && in_range(p)) continue;
    std::string problem = kind_mismatch(static_cast<ParameterKind>(kind), p.value);
    if (problem.empty()) problem = value_problem(out, p);
    if (problem.empty()) continue;
    throw toolpath::InputError({file_, p.line, p.column},
                               fmt::format("parameter `{}` of {}: {}", p.name, out.name, problem));
  }
  if (((present & kXcentre) && (present & kYcentre)) || ((present & kXrel) && (present & kYrel))) present |= kCentre;
  // Only what was read from a trace: a controller model's stream (2XAxisCNC has no Z), read
  // directly or from the trace `postproc read --dialect` wrote (its @start_of_file names the
  // dialect), or a generated one carries what its machine has.
  if (out.line != 0 && !read_back_) {
    if (toolpath::iequals(out.name, "@start_of_file") && out.find("dialect")) read_back_ = true;
    else check_required(out, present);
  }
  given_ |= present;
  return true;
}

void ParameterCheck::check_required(const toolpath::Command& c, std::uint32_t present) {
  const int r = required_of(c.name);
  if (r < 0) return;
  const std::uint32_t lacking = kRequired[r].needs & ~present;
  if (!lacking) return;
  const std::uint32_t need = kRequired[r].needs;
  if (const std::uint32_t never = lacking & ~given_) {
    const int bit = std::countr_zero(never);
    throw toolpath::InputError({file_, c.line, 1},
                               fmt::format("{} has no {}, and no command before it gave one: expected {}, which a "
                                           "trace gives with every {}",
                                           c.name, kNeedNames[bit], need_list(need), c.name));
  }
  // Taken over from an earlier command, as the post's variables would: said once per pair.
  for (int bit = 0; bit < kNeeds; ++bit) {
    if (!(lacking & (1u << bit))) continue;
    const std::uint64_t pair = std::uint64_t{1} << (r * kNeeds + bit);
    if (warned_ & pair) continue;
    warned_ |= pair;
    if (warn_)
      warn_({file_, c.line, 1}, fmt::format("{} has no {}: the last one given stays (a trace gives {} with every {}; "
                                            "further {} commands without it are not reported)",
                                            c.name, kNeedNames[bit], need_list(need), c.name, c.name));
  }
}

}  // namespace postproc
