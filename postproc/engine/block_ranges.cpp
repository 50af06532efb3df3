#include "postproc/engine/block_ranges.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "toolpath/value.hpp"

namespace postproc {

using toolpath::iequals;

BlockRanges::Role BlockRanges::role_of(std::string_view c) {
  if (iequals(c, "@proc") || iequals(c, "@turn_proc")) return Role::OpenSubroutine;
  if (iequals(c, "@end_proc") || iequals(c, "@turn_endproc")) return Role::CloseSubroutine;
  if (iequals(c, "@loop")) return Role::OpenLoop;
  if (iequals(c, "@end_loop")) return Role::CloseLoop;
  if (iequals(c, "@call_proc") || iequals(c, "@call_prms") || iequals(c, "@start_of_job") || iequals(c, "@turning") ||
      iequals(c, "@thread"))
    return Role::CallByLabel;
  return Role::None;
}

BlockRanges::BlockRanges(NewSlot new_slot, Fill fill) : new_slot_(std::move(new_slot)), fill_(std::move(fill)) {}

BlockRanges::Kind BlockRanges::kind_of(Role role) {
  return role == Role::OpenLoop || role == Role::CloseLoop ? Kind::Loop : Kind::Subroutine;
}

std::string BlockRanges::describe(Kind kind, std::int64_t label) {
  return kind == Kind::Loop ? fmt::format("the body of loop {}", label) : fmt::format("the body of subroutine {}", label);
}

BlockRanges::Body* BlockRanges::find_open(std::uint64_t id) {
  for (auto& b : open_)
    if (b.id == id) return &b;
  return nullptr;
}

void BlockRanges::enter(Role role, std::int64_t label) {
  switch (role) {
    case Role::None: return;
    case Role::OpenSubroutine:
    case Role::OpenLoop:
      open_.push_back(Body{kind_of(role), label, next_body_, false, {}, {}});
      running_.push_back({role, next_body_++});
      return;
    case Role::CloseSubroutine:
    case Role::CloseLoop: close(kind_of(role)); break;
    case Role::CallByLabel: break;
  }
  running_.push_back({role, 0});
}

void BlockRanges::leave(Role role) {
  if (role == Role::None) return;
  // Innermost first; a procedure left by an error elsewhere never unbalances the rest.
  auto it = std::find_if(running_.rbegin(), running_.rend(), [&](const Running& r) { return r.role == role; });
  if (it == running_.rend()) return;
  if (Body* b = find_open(it->body)) b->recording = true;  // the body starts after its opener's own output
  running_.erase(std::next(it).base());
}

void BlockRanges::block_numbered(std::int64_t number) {
  for (auto& b : open_) {
    if (!b.recording) continue;
    if (!b.range.first) b.range.first = number;
    b.range.last = number;
  }
}

// The closing procedure ends the innermost open body of its kind (a closer without an opener
// leaves nothing to report: its own start_line/end_line is then an error).
void BlockRanges::close(Kind kind) {
  auto it = std::find_if(open_.rbegin(), open_.rend(), [&](const Body& b) { return b.kind == kind; });
  Closed& last = last_closed_[int(kind)];
  if (it == open_.rend()) {
    last = Closed{};
    return;
  }
  Body body = std::move(*it);
  open_.erase(std::next(it).base());
  last = Closed{true, body.label, body.range};
  const std::string what = describe(kind, body.label);
  for (const Pending& p : body.waiting) resolve(p, body.range, what);
  if (kind == Kind::Subroutine) {
    closed_subroutines_[body.label] = body.range;
    if (auto w = awaiting_label_.find(body.label); w != awaiting_label_.end()) {
      std::vector<Pending> calls = std::move(w->second);
      awaiting_label_.erase(w);
      for (const Pending& p : calls) resolve(p, body.range, what);
    }
  }
}

void BlockRanges::resolve(const Pending& p, const Range& range, const std::string& body) const {
  const auto& value = p.which == gppl::LineFunction::StartLine ? range.first : range.last;
  if (!value)
    throw std::runtime_error(fmt::format("{} at {}: {} has no numbered blocks (is block numbering on there?)",
                                         gppl::name_of(p.which), p.where, body));
  fill_(p.slot, gppl::format_integer(*value, p.format));
}

void BlockRanges::defer(std::vector<Pending>& into, gppl::LineFunction which, std::string_view format,
                        std::string where, std::string& out) {
  std::string marker;
  const std::uint32_t slot = new_slot_(marker);
  out += marker;
  into.push_back(Pending{slot, which, std::string(format), std::move(where)});
}

void BlockRanges::line_function(gppl::LineFunction which, std::string_view format, std::int64_t label,
                                std::string where, std::string& out) {
  if (running_.empty())
    throw std::runtime_error(
        "start_line and end_line belong to @call_proc, @call_prms, @start_of_job, @turning, @thread, @proc, "
        "@end_proc, @turn_proc, @turn_endproc, @loop and @end_loop (and the procedures they call)");
  const Running& r = running_.back();
  auto now = [&](const Range& range, const std::string& body) {
    const auto& value = which == gppl::LineFunction::StartLine ? range.first : range.last;
    if (!value) throw std::runtime_error(fmt::format("{} has no numbered blocks (is block numbering on there?)", body));
    out += gppl::format_integer(*value, format);
  };
  switch (r.role) {
    case Role::None: break;
    case Role::OpenSubroutine:
    case Role::OpenLoop:
      if (Body* b = find_open(r.body)) return defer(b->waiting, which, format, std::move(where), out);
      break;
    case Role::CloseSubroutine:
    case Role::CloseLoop: {
      const Kind kind = kind_of(r.role);
      const Closed& last = last_closed_[int(kind)];
      if (!last.valid)
        throw std::runtime_error(fmt::format("no {} is open here to end", kind == Kind::Loop ? "loop" : "subroutine"));
      return now(last.range, describe(kind, last.label));
    }
    case Role::CallByLabel: {
      for (auto b = open_.rbegin(); b != open_.rend(); ++b) {
        if (b->kind != Kind::Subroutine || b->label != label) continue;
        if (which == gppl::LineFunction::StartLine && b->range.first) return now(b->range, describe(b->kind, label));
        return defer(b->waiting, which, format, std::move(where), out);
      }
      if (auto c = closed_subroutines_.find(label); c != closed_subroutines_.end())
        return now(c->second, describe(Kind::Subroutine, label));
      return defer(awaiting_label_[label], which, format, std::move(where), out);
    }
  }
  throw std::runtime_error("the body is not known here");
}

void BlockRanges::finish() const {
  const Pending* first = nullptr;
  std::string why;
  auto consider = [&](const Pending& p, const std::string& reason) {
    if (first && first->slot < p.slot) return;
    first = &p;
    why = reason;
  };
  for (const auto& b : open_)
    for (const Pending& p : b.waiting)
      consider(p, fmt::format("{} never ended (no {})", describe(b.kind, b.label),
                              b.kind == Kind::Loop ? "@end_loop" : "@end_proc"));
  for (const auto& [label, calls] : awaiting_label_)
    for (const Pending& p : calls) consider(p, fmt::format("no body of subroutine {} followed (no @proc with label {})", label, label));
  if (first) throw std::runtime_error(fmt::format("{} at {}: {}", gppl::name_of(first->which), first->where, why));
}

}  // namespace postproc
