#include "toolpath/parameter_shelf.hpp"

namespace toolpath {

[[gnu::always_inline]] inline ParameterShelf::Label ParameterShelf::label_of(std::string_view name) {
  const std::size_t n = name.size();
  if (n == 0 || n > 16) return {};
  return {load_word(name, 0, n < 8 ? n : 8), n > 8 ? load_word(name, 8, n - 8) : 0, n};
}

void ParameterShelf::exchange(Command& out, std::string_view name) {
  const Label wanted = label_of(name);
  if (wanted.size == 0) {  // a long name: no entry has it, and none is given up for it
    out.name.assign(name);
    return;
  }
  const Label returned = label_of(out.name);
  for (Entry& e : entries_) {
    if (e.label != wanted) continue;
    if (out.parameters.capacity() == 0) {
      out.parameters = e.parameters;  // a fresh command (the pipeline filling up): keep the entry
      out.name.assign(name);
      return;
    }
    // The entry keeps the vector handed back and the name of what it held; its own name is
    // `name` (the same label), which `out` takes by the swap.
    out.parameters.swap(e.parameters);
    out.name.swap(e.name);
    e.label = returned;
    return;
  }
  if (returned.size == 0 || out.parameters.empty()) {  // nothing worth keeping
    out.name.assign(name);
    return;
  }
  Entry& e = entries_[victim_];
  victim_ = (victim_ + 1) % entries_.size();
  out.parameters.swap(e.parameters);
  out.name.swap(e.name);
  out.name.assign(name);
  e.label = returned;
}

void ParameterShelf::keep(const Command& c) {
  const Label label = label_of(c.name);
  if (label.size == 0 || c.parameters.empty()) return;
  Entry* unused = nullptr;
  for (Entry& e : entries_) {
    if (e.label == label) return;
    if (!unused && e.label.size == 0 && e.parameters.capacity() == 0) unused = &e;
  }
  if (!unused) {  // the one-off commands at the start of a job make way for the repeated ones
    unused = &entries_[victim_];
    victim_ = (victim_ + 1) % entries_.size();
  }
  unused->parameters = c.parameters;
  unused->name = c.name;
  unused->label = label;
}

}  // namespace toolpath
