#include "toolpath/parameter_shelf.hpp"

namespace toolpath {

[[gnu::always_inline]] inline ParameterShelf::Label ParameterShelf::label_of(std::string_view name) {
  const std::size_t n = name.size();
  if (n == 0 || n > 16) return {};
  return {load_word(name, 0, n < 8 ? n : 8), n > 8 ? load_word(name, 8, n - 8) : 0, n};
}

void ParameterShelf::exchange(Command& out, std::string_view name) {
  const Label wanted = label_of(name);
  const Label returned = label_of(out.name);
  out.name.assign(name);
  if (wanted.size == 0) return;
  for (Entry& e : entries_) {
    if (e.label == wanted) {
      if (out.parameters.capacity() == 0) {
        out.parameters = e.parameters;  // a fresh command (the pipeline filling up): keep the entry
        return;
      }
      out.parameters.swap(e.parameters);
      e.label = returned;  // the entry now keeps the vector handed back
      return;
    }
  }
  if (returned.size == 0 || out.parameters.empty()) return;  // nothing worth keeping
  Entry& e = entries_[victim_];
  victim_ = (victim_ + 1) % entries_.size();
  out.parameters.swap(e.parameters);
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
  unused->label = label;
}

}  // namespace toolpath
