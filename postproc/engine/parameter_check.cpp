#include "postproc/engine/parameter_check.hpp"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "toolpath/bounded_read.hpp"
#include "toolpath/error.hpp"
#include "toolpath/short_text.hpp"
#include "toolpath/trace_reader.hpp"

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

// The entry of kRequired for command `name`, -1 for none: by length first (each command of the
// list has its own length but @drill_point and @change_tool), then one comparison.
inline int required_of(std::string_view name) {
  auto is = [&](int i) { return toolpath::iequals(name, kRequired[i].command); };
  switch (name.size()) {
    case 4: return is(2) ? 2 : -1;
    case 5: return is(1) ? 1 : -1;
    case 11: return is(0) ? 0 : -1;
    case 12: return is(3) ? 3 : is(4) ? 4 : -1;
    default: return -1;
  }
}
static_assert(kRequired[0].command.size() == 11 && kRequired[1].command.size() == 5 && kRequired[2].command.size() == 4 &&
              kRequired[3].command.size() == 12 && kRequired[4].command.size() == 12 && std::size(kRequired) == 5);

// The Need bit each keyed parameter stands for (the centre counts in halves, put together below).
enum Half : std::uint32_t { kXcentre = 128, kYcentre = 256, kXrel = 512, kYrel = 1024 };

// The fast path's ranges for a Numeric value (`low <= x <= high`, which NaN fails).
struct Range {
  double low, high;
};
enum : std::uint8_t { kFinite, kIntegerRange, kFeedRange, kRadiusRange, kAnyNumber };
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr Range kRanges[] = {
    {-kMax, kMax},                                           // a Numeric parameter: finite
    {-999999999.0, 999999999.0},                             // an Integer parameter
    {0.0, kMax},                                             // feed: 0 or more
    {std::numeric_limits<double>::denorm_min(), kMax},       // radius: above 0
    {-kInf, kInf},                                           // an Enum parameter, or none in the catalogue
};

// Per key: the Need bit it stands for (the centre counts in halves, put together in next()), and
// the value kinds (bit 1 << ValueKind) that `accepts` and `in_range` surely take for it; a Numeric
// value also has to lie in its kRanges entry. What is not marked here goes to check_slow, which
// decides by the general rule, so a bit left out costs time, never a verdict. The key `none`
// marks nothing: a name outside the key list is looked up by name. A TraceReader screens the
// values it reads by the same table (toolpath::ValueScreen).
const std::array<toolpath::ValueScreen, toolpath::param_key_count + 1>& key_checks() {
  static const auto table = [] {
    std::array<toolpath::ValueScreen, toolpath::param_key_count + 1> t{};
    std::array<std::uint8_t, toolpath::param_key_count + 1> range;
    range.fill(kAnyNumber);
    using K = toolpath::ParamKey;
    constexpr auto bit = [](ValueKind k) { return static_cast<std::uint8_t>(1u << static_cast<unsigned>(k)); };
    const std::uint8_t I = bit(ValueKind::Integer), N = bit(ValueKind::Numeric), L = bit(ValueKind::Logical),
                       S = bit(ValueKind::String), E = bit(ValueKind::Enum);
    const auto& kinds = kinds_by_key();
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (k == static_cast<std::size_t>(K::none)) continue;
      std::uint8_t& ok = t[k].kinds;
      switch (kinds[k]) {
        case int(ParameterKind::Numeric): ok = I | N | L, range[k] = kFinite; break;
        case int(ParameterKind::Integer): ok = I | N | L | E, range[k] = kIntegerRange; break;
        case int(ParameterKind::Logical): ok = L; break;  // numbers: 0 or 1, by the general rule
        case int(ParameterKind::String): ok = S | E; break;
        case int(ParameterKind::Enum): ok = I | N | L | E; break;
        default: ok = I | N | L | S | E; break;  // not in the catalogue: nothing to check
      }
    }
    // in_range: a feed of 0 or more, a radius above 0 (integers take the general rule).
    for (auto [key, key_range] : {std::pair{K::feed, kFeedRange}, std::pair{K::radius, kRadiusRange}}) {
      const auto k = static_cast<std::size_t>(key);
      const bool numeric = kinds[k] == int(ParameterKind::Numeric);
      t[k].kinds = numeric ? static_cast<std::uint8_t>(t[k].kinds & ~I) : 0;
      range[k] = key_range;
    }
    const std::pair<K, std::uint32_t> bits[] = {{K::xpos, kX},          {K::ypos, kY},           {K::zpos, kZ},
                                                {K::feed, kFeed},       {K::arc_direction, kDirection},
                                                {K::xcenter, kXcentre}, {K::ycenter, kYcentre},  {K::xcenter_rel, kXrel},
                                                {K::ycenter_rel, kYrel}, {K::tool_number, kTool}};
    for (auto [key, need] : bits) t[static_cast<std::size_t>(key)].need = static_cast<std::uint16_t>(need);
    for (std::size_t k = 0; k < t.size(); ++k) t[k].low = kRanges[range[k]].low, t[k].high = kRanges[range[k]].high;
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

ParameterCheck::ParameterCheck(toolpath::CommandSource& inner, std::string file_name, Warn warn, Deeper deeper)
    : inner_(inner), file_(std::move(file_name)), warn_(std::move(warn)), leave_deeper_(deeper == Deeper::Leave) {
  // A trace reader screens the values as it reads them, by the fast path's table below: a command
  // whose every parameter passed needs no second look here.
  if (auto* reader = dynamic_cast<toolpath::TraceReader*>(&inner)) {
    reader->screen_values(key_checks().data());
    screening_ = reader;
  }
}

int ParameterCheck::unkeyed_kind(const toolpath::Parameter& p) {
  const std::string& name = p.name;
  const std::size_t n = name.size();
  const std::uint64_t head = toolpath::load_word(name, 0, n < 8 ? n : 8);
  RecentName& recent = recent_unkeyed_[((head ^ n) * 0x9E3779B97F4A7C15ull) >> 58];
  if (recent.kind != -2 && toolpath::same_short_text(recent.name, name)) return recent.kind;
  auto it = unkeyed_.find(name);
  if (it == unkeyed_.end()) {
    if (unkeyed_.size() > 4096) unkeyed_.clear();  // a stream of ever new names: keep memory flat
    const ParameterSpec* spec = find_parameter(name);
    it = unkeyed_.emplace(name, spec ? static_cast<int>(spec->kind) : -1).first;
  }
  recent.name.assign(name);
  recent.kind = it->second;
  return it->second;
}

// One load per parameter decides the common case: the Need bit the parameter stands for, and the
// value kinds its catalogue kind takes as they are (see key_checks). Anything else, and every
// parameter without a key, goes to check_slow, which applies the general rule.
bool ParameterCheck::next(toolpath::Command& out) {
  do {
    if (!inner_.next(out)) return false;
    // What the original post did itself: kept as written, or left out.
    if (!out.is_stream_command() && !leave_deeper_) return true;
  } while (!out.is_stream_command());
  std::uint32_t present = 0;
  if (!screening_ || !screening_->screened(present)) {
    present = 0;
    const auto& checks = key_checks();
    for (const toolpath::Parameter& p : out.parameters) {
      const toolpath::ValueScreen& e = checks[static_cast<std::size_t>(p.key)];
      present |= e.need;
      if (!e.passes(p.value)) check_slow(out, p);
    }
  }
  if (((present & kXcentre) && (present & kYcentre)) || ((present & kXrel) && (present & kYrel))) present |= kCentre;
  // Only what was read from a trace: a controller model's stream (2XAxisCNC has no Z), read
  // directly or from the trace `postproc read --dialect` wrote (its @start_of_file names the
  // dialect), or a generated one carries what its machine has.
  if (out.line != 0 && !read_back_) {
    if (const int r = required_of(out.name); r >= 0 && (kRequired[r].needs & ~present) != 0)
      report_missing(out, r, present);
    else if (r < 0 && toolpath::iequals(out.name, "@start_of_file") && out.find("dialect"))
      read_back_ = true;
  }
  given_ |= present;
  return true;
}

// The general rule for one parameter: its catalogue kind (from its key, or looked up by name),
// the value's kind and range; throws at the value's position when they do not agree.
void ParameterCheck::check_slow(const toolpath::Command& out, const toolpath::Parameter& p) {
  const int kind = p.key != toolpath::ParamKey::none ? kinds_by_key()[static_cast<std::size_t>(p.key)] : unkeyed_kind(p);
  if (kind < 0) return;
  if (accepts(static_cast<ParameterKind>(kind), p.value) && in_range(p)) return;
  std::string problem = kind_mismatch(static_cast<ParameterKind>(kind), p.value);
  if (problem.empty()) problem = value_problem(out, p);
  if (problem.empty()) return;
  throw toolpath::InputError({file_, p.line, p.column}, fmt::format("parameter `{}` of {}: {}", p.name, out.name, problem));
}

void ParameterCheck::report_missing(const toolpath::Command& c, int r, std::uint32_t present) {
  const std::uint32_t need = kRequired[r].needs;
  const std::uint32_t lacking = need & ~present;  // not 0: next() calls only then
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
