// The script's parameter dialog without a user (spec sections 6 and 10.2): SetArg definitions and
// the layout routines recorded as the dialog would show them, overrides validated against the
// widget kind, and the dialog described as JSON.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "machines/pikocnc/script/value.hpp"

namespace pikocnc::script {

enum class Widget : std::uint8_t { Float, Integer, Boolean, Combo, Text };

struct ArgDef {
  std::string label;                // without the combo's `*` and items
  Widget widget = Widget::Float;
  std::vector<std::string> items;   // combo
  Value value;
};

class Dialog {
public:
  static constexpr std::int64_t kMaxArg = 50;  // "at most 50": numbers 0..50 (spec 12, point 9)

  // Errors throw OpError.
  void set_arg(std::int64_t num, const std::string& text, const Value& v);
  const Value& arg(std::int64_t num) const;
  void show(std::int64_t num);
  void new_page(const std::string& title);
  void page_title(const std::string& title);
  void separator(const std::string& text);
  void picture(const std::string& name) { picture_ = name; }
  // ArgEdit: applies the overrides (number as text -> value text).
  void apply(const std::map<std::string, std::string>& overrides);
  std::string json() const;
  bool edited() const { return edited_; }

private:
  struct Item {
    std::int64_t arg = -1;  // -1: a separator
    std::string text;
  };
  struct Tab {
    std::string title;
    std::vector<Item> items;
  };
  std::map<std::int64_t, ArgDef> args_;
  std::vector<Tab> tabs_{Tab{}};
  bool layout_ = false;
  bool edited_ = false;
  std::string picture_;
};

}  // namespace pikocnc::script
