// Spec 6.2 (widget kinds), 6.3 (layout rules), 10.2 (ArgEdit, override validation, JSON).
#include "machines/pikocnc/script/dialog.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "machines/pikocnc/script/ops.hpp"

namespace pikocnc::script {

namespace {

std::string lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return s;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += char(c);
    else if (c == '\n') out += "\\n";
    else if (c == '\t') out += "\\t";
    else if (c < 0x20) out += fmt::format("\\u{:04x}", c);
    else out += char(c);
  }
  return out + "\"";
}

std::string json_value(const Value& v) {
  switch (v.kind) {
    case Kind::Boolean: return v.b ? "true" : "false";
    case Kind::String: return json_string(v.s);
    case Kind::Integer: return std::to_string(v.i);
    default: {
      std::string s = float_to_str(v.f);
      if (s.find_first_of(".E") == std::string::npos) s += ".0";  // keep floats recognisable
      return s;
    }
  }
}

const char* widget_name(Widget w) {
  switch (w) {
    case Widget::Float: return "float";
    case Widget::Integer: return "integer";
    case Widget::Boolean: return "boolean";
    case Widget::Combo: return "combo";
    case Widget::Text: return "string";
  }
  return "?";
}

bool parse_integer(const std::string& text, std::int64_t& out) {
  if (text.empty() || text.size() > 11) return false;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (*end != '\0' || v < -2147483648LL || v > 2147483647LL) return false;
  out = v;
  return true;
}

}  // namespace

void Dialog::set_arg(std::int64_t num, const std::string& text, const Value& v) {
  if (num < 0 || num > kMaxArg) throw OpError(fmt::format("argument number {} is out of range 0..{}", num, kMaxArg));
  ArgDef def;
  def.value = v;
  def.label = text;
  switch (v.kind) {
    case Kind::Float: def.widget = Widget::Float; break;
    case Kind::Boolean: def.widget = Widget::Boolean; break;
    case Kind::String: def.widget = Widget::Text; break;
    default: def.widget = Widget::Integer; break;
  }
  if (v.kind == Kind::Integer && !text.empty() && text[0] == '*') {
    // '*Title/a/b/c': a combo box titled Title with items a, b, c; v is the selected index.
    def.widget = Widget::Combo;
    std::size_t start = 1, slash;
    std::vector<std::string> parts;
    while ((slash = text.find('/', start)) != std::string::npos) {
      parts.push_back(text.substr(start, slash - start));
      start = slash + 1;
    }
    parts.push_back(text.substr(start));
    def.label = parts.front();
    def.items.assign(parts.begin() + 1, parts.end());
    if (v.i < 0 || v.i >= std::int64_t(def.items.size()))
      throw OpError(fmt::format("combo box `{}` has {} item(s); index {} selects none", def.label, def.items.size(), v.i));
  }
  args_[num] = std::move(def);
}

const Value& Dialog::arg(std::int64_t num) const {
  auto it = args_.find(num);
  if (it == args_.end()) throw OpError(fmt::format("argument {} is not defined (SetArg({}, ...) first)", num, num));
  return it->second.value;
}

void Dialog::show(std::int64_t num) {
  if (!args_.count(num)) throw OpError(fmt::format("ArgShow({}): argument {} is not defined (SetArg first)", num, num));
  layout_ = true;
  tabs_.back().items.push_back({num, {}});
}

void Dialog::new_page(const std::string& title) {
  layout_ = true;
  tabs_.push_back({title, {}});
}

void Dialog::page_title(const std::string& title) {
  layout_ = true;
  tabs_.front().title = title;
}

void Dialog::separator(const std::string& text) {
  layout_ = true;
  tabs_.back().items.push_back({-1, text});
}

void Dialog::apply(const std::map<std::string, std::string>& overrides) {
  if (!layout_ && !edited_) {
    // No layout routine ran: every argument on one tab, by number (spec 6.3).
    for (const auto& [num, def] : args_) tabs_.front().items.push_back({num, {}});
  }
  edited_ = true;
  for (const auto& [key, raw] : overrides) {
    std::int64_t num = 0;
    if (!parse_integer(key, num)) throw OpError(fmt::format("argument override `{}`: not an argument number", key));
    auto it = args_.find(num);
    if (it == args_.end()) throw OpError(fmt::format("argument {} is not defined by the script (override `{}={}`)", num, key, raw));
    ArgDef& def = it->second;
    std::string text = raw;
    const std::string& given = raw;  // a structured binding cannot be captured (C++20 before P1091 in clang 14)
    auto bad = [&](const char* want) {
      const char* kind = widget_name(def.widget);
      const char* article = kind[0] == 'i' ? "an" : "a";
      return OpError(fmt::format("argument {} (`{}`) is {} {} field: `{}` is not {}", num, def.label, article, kind, given, want));
    };
    switch (def.widget) {
      case Widget::Float: {
        for (char& c : text)
          if (c == ',') c = '.';
        char* end = nullptr;
        const double d = std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0' || !std::isfinite(d) || text.find_first_of("xXnN") != std::string::npos)
          throw bad("a number");
        def.value = Value::real(d);
        break;
      }
      case Widget::Integer: {
        std::int64_t v = 0;
        if (!parse_integer(text, v)) throw bad("an integer");
        def.value = Value::integer(v);
        break;
      }
      case Widget::Boolean: {
        const std::string t = lower(text);
        if (t == "true" || t == "yes" || t == "1") def.value = Value::boolean(true);
        else if (t == "false" || t == "no" || t == "0") def.value = Value::boolean(false);
        else throw bad("true/false, yes/no or 1/0");
        break;
      }
      case Widget::Combo: {
        std::int64_t index = -1;
        for (std::size_t i = 0; i < def.items.size(); ++i)
          if (def.items[i] == text) index = std::int64_t(i);
        if (index < 0 && parse_integer(text, index) && (index < 0 || index >= std::int64_t(def.items.size())))
          throw bad(fmt::format("an item's index (0..{})", def.items.size() - 1).c_str());
        if (index < 0) throw bad("one of its items or an index");
        def.value = Value::integer(index);
        break;
      }
      case Widget::Text:
        if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') && text.back() == text.front())
          text = text.substr(1, text.size() - 2);
        def.value = Value::text(text);
        break;
    }
  }
}

std::string Dialog::json() const {
  std::string out = "{\n  \"picture\": " + (picture_.empty() ? std::string("null") : json_string(picture_)) + ",\n  \"tabs\": [";
  for (std::size_t t = 0; t < tabs_.size(); ++t) {
    out += t ? ",\n    {" : "\n    {";
    out += "\"title\": " + json_string(tabs_[t].title) + ", \"items\": [";
    for (std::size_t i = 0; i < tabs_[t].items.size(); ++i) {
      const Item& item = tabs_[t].items[i];
      out += i ? ",\n      " : "\n      ";
      if (item.arg < 0) {
        out += "{\"separator\": " + json_string(item.text) + "}";
        continue;
      }
      const ArgDef& def = args_.at(item.arg);
      out += fmt::format("{{\"arg\": {}, \"label\": {}, \"kind\": \"{}\"", item.arg, json_string(def.label), widget_name(def.widget));
      if (def.widget == Widget::Combo) {
        out += ", \"items\": [";
        for (std::size_t k = 0; k < def.items.size(); ++k) out += (k ? ", " : "") + json_string(def.items[k]);
        out += "]";
      }
      out += ", \"value\": " + json_value(def.value) + "}";
    }
    out += tabs_[t].items.empty() ? "]}" : "\n    ]}";
  }
  out += "\n  ]\n}\n";
  return out;
}

}  // namespace pikocnc::script
