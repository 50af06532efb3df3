// SolidCAM machine ID files (VMID, XML with the root <Machine>) read into the PRP model: mapped
// controller attributes become PRP parameters, <DrillCycle>s drill_type records, <WireEdmMacro>s
// wc_macro records, <UserDefParams>
// PRP external variables, the rotary axes' travel (RotaryLimits). Everything else (kinematics,
// devices, simulation data) is skipped.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <vector>

#include <fmt/format.h>
#include <pugixml.hpp>

#include "prp/params/grammar.hpp"
#include "prp/params/loader.hpp"
#include "prp/params/vmid_map.hpp"

namespace prp {
namespace {

constexpr std::size_t kMaxNameLength = 60;  // GPPL identifier limit, as for PRP record names

std::optional<double> to_number(std::string_view t) {
  if (!grammar::matches<grammar::number>(t)) return std::nullopt;
  double d = 0;
  auto [ptr, ec] = std::from_chars(t.data() + (t[0] == '+'), t.data() + t.size(), d);
  if (ec != std::errc{} || ptr != t.data() + t.size() || std::abs(d) > 1e300) return std::nullopt;
  return d;
}

std::optional<std::int64_t> to_integer(std::string_view t) {
  if (!grammar::matches<grammar::integer>(t)) {
    // SolidCAM writes whole numbers of integer parameters with decimals too: DefaultValue="3.000000".
    auto d = to_number(t);
    if (!d || *d != std::trunc(*d) || std::abs(*d) > 999999999) return std::nullopt;
    return static_cast<std::int64_t>(*d);
  }
  if (t[0] == '+') t.remove_prefix(1);
  std::int64_t v = 0;
  auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc{} || ptr != t.data() + t.size() || v > 999999999 || v < -999999999) return std::nullopt;
  return v;
}

std::optional<bool> to_flag(std::string_view t) {
  if (t == "1" || toolpath::iequals(t, "true")) return true;
  if (t == "0" || toolpath::iequals(t, "false")) return false;
  return std::nullopt;
}

bool valid_name(std::string_view name) {
  return name.size() <= kMaxNameLength && grammar::matches<grammar::identifier>(name);
}

class VmidReader {
public:
  VmidReader(Loader& loader, std::string_view text) : loader_(loader), text_(text), buffer_(text) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') line_starts_.push_back(i + 1);
  }

  void read() {
    pugi::xml_parse_result result =
        doc_.load_buffer_inplace(buffer_.data(), buffer_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) {
      loader_.error_at(at(static_cast<std::size_t>(std::max<std::ptrdiff_t>(result.offset, 0))),
                       fmt::format("malformed XML: {} (expected a well-formed SolidCAM VMID file)",
                                   result.description()));
      return;
    }
    pugi::xml_node root = doc_.document_element();
    if (!root) return loader_.error_at(at(0), "expected a <Machine> element (a SolidCAM VMID file)");
    if (std::string_view(root.name()) != "Machine")
      return loader_.error_at(at(root), fmt::format("expected the root element <Machine> of a SolidCAM VMID file, "
                                                    "found <{}>", root.name()));
    walk(root);
    rotary_axes(root);
  }

private:
  toolpath::SourcePosition at(std::size_t offset) const {
    auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
    const std::size_t line = static_cast<std::size_t>(it - line_starts_.begin());
    return {loader_.file_name(), line, offset - line_starts_[line - 1] + 1};
  }
  toolpath::SourcePosition at(pugi::xml_node node) const {
    const std::ptrdiff_t offset = node.offset_debug();  // the name, just after '<'
    return at(offset > 0 ? static_cast<std::size_t>(offset - 1) : 0);
  }
  // The attribute's value (in-place parsing keeps it inside the buffer), else its element.
  toolpath::SourcePosition at(pugi::xml_attribute attribute, pugi::xml_node owner) const {
    const char* v = attribute.value();
    if (v >= buffer_.data() && v <= buffer_.data() + buffer_.size())
      return at(static_cast<std::size_t>(v - buffer_.data()));
    return at(owner);
  }

  void walk(pugi::xml_node root) {
    std::vector<pugi::xml_node> stack{root};
    while (!stack.empty()) {
      pugi::xml_node node = stack.back();
      stack.pop_back();
      const std::string_view name = node.name();
      if (name == "DrillCycle" || name == "WireEdmMacro") {
        cycle(node, name == "DrillCycle" ? "drill_type" : "wc_macro");
        continue;
      }
      if (name == "UserDefParams") {
        user_parameters(node);
        continue;
      }
      mapped_attributes(node);
      // Children in document order (the stack reverses them); machine components are kinematics.
      std::vector<pugi::xml_node> children;
      for (pugi::xml_node child : node.children())
        if (child.type() == pugi::node_element && std::string_view(child.name()) != "Components")
          children.push_back(child);
      stack.insert(stack.end(), children.rbegin(), children.rend());
    }
  }

  // The machine's rotary axes (<Axis Type="1"> anywhere in its components) and their travel.
  void rotary_axes(pugi::xml_node root) {
    std::vector<pugi::xml_node> stack{root};
    while (!stack.empty()) {
      pugi::xml_node node = stack.back();
      stack.pop_back();
      for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling())
        if (child.type() == pugi::node_element) stack.push_back(child);  // popped in document order
      if (std::string_view(node.name()) != "Axis" || std::string_view(node.attribute("Type").value()) != "1") continue;
      const std::string_view name = node.attribute("Name").value();
      if (name.size() != 1 || !std::strchr("ABCabc", name[0])) continue;  // a named spindle, a turret
      const auto min = to_number(node.attribute("MinLim").value());
      const auto max = to_number(node.attribute("MaxLim").value());
      if (!min || !max || *min > *max) {
        loader_.warning_at(at(node), fmt::format("rotary axis {}: MinLim and MaxLim are no range of degrees; its "
                                                 "travel is not checked", name));
        continue;
      }
      loader_.add_rotary_limits({static_cast<char>(std::toupper(static_cast<unsigned char>(name[0]))), *min, *max,
                                 at(node)});
    }
  }

  void mapped_attributes(pugi::xml_node node) {
    const std::string_view element = node.name();
    for (const VmidAttribute& m : vmid_attributes()) {
      if (m.element != element) continue;
      pugi::xml_attribute a = node.attribute(std::string(m.attribute).c_str());
      if (!a) continue;
      const KeyInfo* info = find_key(m.key);
      if (!info || info->kind != vmid_kind(m.value)) continue;  // the table test keeps these in step
      Parameter p;
      p.key = std::string(info->name);
      p.kind = info->kind;
      p.raw = a.value();
      p.where = at(a, node);
      if (!convert(m, p)) continue;
      loader_.add_parameter(std::move(p));  // the first element that sets a key wins
    }
  }

  bool convert(const VmidAttribute& m, Parameter& p) {
    const std::string_view t = p.raw;
    if (t.empty() && m.value != VmidValue::Text) return false;  // not set: the engine default applies
    auto bad = [&](std::string_view expected) {
      loader_.error_at(p.where, fmt::format("{}=\"{}\" (PRP {}): expected {}", m.attribute, t, p.key, expected));
      return false;
    };
    switch (m.value) {
      case VmidValue::Flag: {
        auto v = to_flag(t);
        if (!v) return bad("0 or 1");
        p.logical = *v;
        return true;
      }
      case VmidValue::Integer: {
        auto v = to_integer(t);
        if (!v) return bad("an integer (-999999999 .. 999999999)");
        p.integer = *v;
        return true;
      }
      case VmidValue::Number:
      case VmidValue::Length: {
        auto v = to_number(t);
        if (!v) return bad("a number");
        p.metric[0] = p.inch[0] = *v;
        if (m.value == VmidValue::Length) {  // VMID lengths are millimetres
          p.inch[0] = *v / 25.4;
          p.has_inch_half = true;
        }
        return true;
      }
      case VmidValue::Text:
        p.text = p.raw;
        return true;
      case VmidValue::GenProcs:
        if (t == "0" || t == "1") {
          p.text.assign(1, t == "1" ? 'Y' : 'N');  // one char: GCC 12's -Wrestrict misfires on `= "Y"` here
          return true;
        }
        loader_.warning_at(p.where, fmt::format("GenProc=\"{}\" is not a code we know (0: N, 1: Y): gen_procs keeps "
                                                "its default", t));
        return false;
      case VmidValue::MachineType:
        if (t != "6") return false;  // milling and the codes we have not seen: no machine_type
        p.text = "WIRE_CUT";
        return true;
    }
    return false;
  }

  // The value a <Param> starts at: its Value, or DefaultValue when Value is empty (user parameters
  // and cycle parameters alike); nullopt after an error.
  std::optional<toolpath::Value> param_value(pugi::xml_node param, VarType type) {
    pugi::xml_attribute value = param.attribute("Value");
    if (!value || !*value.value()) value = param.attribute("DefaultValue");
    return user_value(type, param.attribute("ValueType").value(), value.value(), at(value, param));
  }

  // A user parameter's value by ValueType; nullopt after an error.
  std::optional<toolpath::Value> user_value(VarType type, std::string_view value_type, std::string_view t,
                                            const toolpath::SourcePosition& where) {
    auto bad = [&](std::string_view expected) {
      loader_.error_at(where, fmt::format("Value=\"{}\": expected {} (ValueType {})", t, expected, value_type));
      return std::nullopt;
    };
    switch (type) {
      case VarType::String: return toolpath::Value::make_string(std::string(t));
      case VarType::Logical: {
        if (t.empty()) return toolpath::Value::make_logical(false);
        auto v = to_flag(t);
        if (!v) return bad("0 or 1, a yes/no option");
        return toolpath::Value::make_logical(*v);
      }
      case VarType::Integer: {
        if (t.empty()) return toolpath::Value::make_integer(0);
        auto v = to_integer(t);
        if (!v) return bad("an integer");
        return toolpath::Value::make_integer(*v);
      }
      case VarType::Numeric: {
        if (t.empty()) return toolpath::Value::make_numeric(0.0);
        auto v = to_number(t);
        if (!v) return bad("a number");
        return toolpath::Value::make_numeric(*v);
      }
    }
    return std::nullopt;
  }

  // The GPPL type of a <Param>'s ValueType; unknown types are kept as text, with a warning.
  VarType param_type(pugi::xml_node param) {
    pugi::xml_attribute vt = param.attribute("ValueType");
    if (auto type = vmid_value_type(vt.value())) return *type;
    loader_.warning_at(at(vt, param), fmt::format("ValueType=\"{}\" of `{}`: expected 1 to 5; kept as text",
                                                  vt.value(), param.attribute("GppName").value()));
    return VarType::String;
  }

  // A GppName that must become a GPPL identifier; nullopt after an error.
  std::optional<std::string> gpp_name(pugi::xml_node node) {
    pugi::xml_attribute a = node.attribute("GppName");
    if (valid_name(a.value())) return std::string(a.value());
    loader_.error_at(at(a, node), fmt::format("GppName=\"{}\": expected a name (a letter, then letters, digits or "
                                              "'_', at most 60 characters)", a.value()));
    return std::nullopt;
  }

  // <MachineParams> are the machine's options (PRP `options`); the per-job-type lists
  // (<MillParamsJobs>, ...) are job options (`job_opt_type`). Each <Param>/<ParamJobs> declares a
  // variable that starts at its Value (DefaultValue when Value is empty).
  void user_parameters(pugi::xml_node node) {
    for (pugi::xml_node list : node.children()) {
      if (list.type() != pugi::node_element) continue;
      const std::string_view by = std::string_view(list.name()) == "MachineParams" ? "options" : "job_opt_type";
      for (pugi::xml_node param : list.children()) {
        if (param.type() != pugi::node_element || !param.attribute("GppName")) continue;
        auto name = gpp_name(param);
        if (!name) continue;
        const VarType type = param_type(param);
        auto where = at(param.attribute("GppName"), param);
        auto initial = param_value(param, type);
        if (!initial) continue;
        if (std::string_view(param.attribute("IsStateActive").value()) == "0") initial.reset();
        if (!declared(by, *name)) {
          Record r;
          r.key = std::string(by);
          r.form = Record::Form::Declaration;
          r.name = *name;
          r.type = type;
          r.raw = fmt::format("{} {}", *name, type_name(type));
          r.where = r.name_where = where;
          loader_.add_record(std::move(r));
        }
        loader_.declare(*name, type, std::move(initial), by, where);
      }
    }
  }

  // The same name in several job lists (milling, turning, ...) is one variable.
  bool declared(std::string_view by, std::string_view name) {
    for (const auto& [b, n] : declared_)
      if (b == by && toolpath::iequals(n, name)) return true;
    declared_.emplace_back(std::string(by), std::string(name));
    return false;
  }

  // A <DrillCycle> (drill_type) or a wire <WireEdmMacro> (wc_macro, whose word is None as in the
  // PRPs SolidCAM writes: `wc_macro = P8000 None Y XX YY ...`): a cycle record whose <CycleParams>
  // each declare a variable.
  void cycle(pugi::xml_node node, std::string_view key) {
    auto name = gpp_name(node);
    if (!name) return;
    Record r;
    r.key = std::string(key);
    r.form = Record::Form::Cycle;
    r.name = *name;
    r.where = r.name_where = at(node.attribute("GppName"), node);
    if (key == "wc_macro") {
      r.base = "None";
    } else if (pugi::xml_attribute dt = node.attribute("DrillType"); auto base = vmid_drill_base(dt.value())) {
      r.base = std::string(*base);
    } else {
      loader_.warning_at(at(dt, node), fmt::format("DrillType=\"{}\" of `{}`: expected 0 to 6; the cycle has no base "
                                                   "type (None)", dt.value(), *name));
      r.base = "NONE";
    }
    r.flag = std::string_view(node.attribute("UseCycle").value()) != "0";
    struct CycleParam {
      std::string name;
      VarType type;
      toolpath::SourcePosition where;
      toolpath::Value initial;
    };
    std::vector<CycleParam> params;
    for (pugi::xml_node param : node.child("CycleParams").children()) {
      if (param.type() != pugi::node_element || !param.attribute("GppName")) continue;
      auto p = gpp_name(param);
      if (!p) return;
      const VarType type = param_type(param);
      auto initial = param_value(param, type);
      if (!initial) return;
      params.push_back({*p, type, at(param.attribute("GppName"), param), std::move(*initial)});
      r.params.push_back(*p);
    }
    r.raw = fmt::format("{} {} {}", r.name, r.base, *r.flag ? "Y" : "N");
    for (const auto& p : params) r.raw += " " + p.name;
    if (!loader_.add_record(std::move(r))) return;
    // Cycle parameters hold the VMID's value (the job dialog's default) but stay inactive until the
    // toolpath's command sets them, as in a PRP.
    for (auto& p : params)
      if (!loader_.declare(p.name, p.type, std::move(p.initial), key, p.where)) break;
  }

  Loader& loader_;
  std::string_view text_;
  std::string buffer_;  // parsed in place: attribute values point into it
  std::vector<std::size_t> line_starts_;
  pugi::xml_document doc_;
  std::vector<std::pair<std::string, std::string>> declared_;
};

}  // namespace

void Loader::add_rotary_limits(RotaryLimits limits) {
  for (const RotaryLimits& known : params_.rotary_limits_)
    if (known.axis == limits.axis) return;
  params_.rotary_limits_.push_back(std::move(limits));
}

MachineParameters Loader::run_vmid(std::string_view text) {
  VmidReader(*this, text).read();
  return finish();
}

}  // namespace prp
