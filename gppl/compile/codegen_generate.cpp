// Code generation of generate statements `{ ... }` (spec 6.1, 6.4, 6.5).
#include <fmt/format.h>

#include "gppl/compile/compiler.hpp"
#include "gppl/builtins/display_format.hpp"
#include "gppl/error_codes.hpp"
#include "gppl/compile/grammar.hpp"

namespace gppl {

namespace g = gppl::grammar;

namespace {

std::uint32_t global_cell_of(const VarRef& r) { return r.local || r.indices != kNone ? kNone : r.cell; }

}  // namespace

void Compiler::generate(const SyntaxNode& n, Context& ctx, SourcePos pos) {
  const auto first = std::uint32_t(program_->items.size());
  for (const auto& item : n.children) generate_item(*item, ctx, false);
  emit(OpCode::Generate, pos, first, std::uint32_t(program_->items.size()) - first);
}

void Compiler::generate_item(const SyntaxNode& n, Context& ctx, bool in_group) {
  GenItem item;
  item.pos = node_pos(n, ctx.file);
  auto& items = program_->items;
  if (n.is_type<g::gen_nb>() || n.is_type<g::gen_nl>()) {
    item.kind = n.is_type<g::gen_nb>() ? ItemKind::NewBlock : ItemKind::NewLine;
    items.push_back(item);
    return;
  }
  if (n.is_type<g::gen_col>() || n.is_type<g::gen_colrel>()) {
    item.kind = n.is_type<g::gen_col>() ? ItemKind::Col : ItemKind::ColRel;
    item.a = expression(*n.children[0], ctx);
    items.push_back(item);
    return;
  }
  if (n.is_type<g::gen_group>()) {
    const auto index = std::uint32_t(items.size());
    item.kind = ItemKind::Group;
    items.push_back(item);
    for (const auto& member : n.children) generate_item(*member, ctx, true);
    std::vector<std::uint32_t> required;
    bool has_gcode = false;
    for (std::uint32_t i = index + 1; i < items.size(); ++i) {
      const GenItem& m = items[i];
      if (m.kind != ItemKind::Value) continue;
      if (m.ref != kNone) {
        required.push_back(m.ref);
        const VarRef& r = program_->refs[m.ref];
        if (!r.local && r.id == program_->slots.gcode) has_gcode = true;
      } else {
        collect_refs(m.a, required);
      }
    }
    GenItem& group = items[index];
    group.a = std::uint32_t(items.size()) - index - 1;
    group.required = std::uint32_t(program_->lists.size());
    group.required_count = std::uint32_t(required.size());
    group.has_gcode = has_gcode;
    group.text_value_pair =
        group.a == 2 && items[index + 1].kind == ItemKind::Text && items[index + 2].kind == ItemKind::Value;
    if (required.size() == 1) group.global_cell = global_cell_of(program_->refs[required[0]]);
    program_->lists.insert(program_->lists.end(), required.begin(), required.end());
    return;
  }
  (void)in_group;
  // gen_value: operand [':' format]
  const SyntaxNode& operand = *n.children[0];
  if (operand.is_type<g::string_literal>()) {
    item.kind = ItemKind::Text;
    program_->constants.push_back(Value::of_string(literal_text(operand, ctx.file)));
    item.a = std::uint32_t(program_->constants.size() - 1);
    items.push_back(item);  // an explicit format on a string is ignored (6.4)
    return;
  }
  item.kind = ItemKind::Value;
  item.site = program_->format_sites++;
  if (auto f = line_function_of(operand)) {
    // start_line/end_line: the host supplies the number (or a placeholder) when the item runs.
    item.kind = ItemKind::LineFunction;
    item.a = std::uint32_t(*f);
    program_->uses_line_functions = true;
  } else if (operand.is_type<g::variable>()) {
    item.a = expression(operand, ctx);
    item.ref = program_->nodes[item.a].a;
    const VarRef& r = program_->refs[item.ref];
    item.global_cell = global_cell_of(r);
    if (r.index_count == 0) {
      // Rule 2 of 6.4: a string variable `name_f` (system, global or local) formats `name`.
      const std::string format_name = std::string(operand.children[0]->string_view()) + "_f";
      const auto& locals = procedure_sources_[ctx.procedure].locals;
      if (auto it = locals.find(lower(format_name)); it != locals.end()) {
        const LocalVariable& l = program_->procedures[ctx.procedure].locals[it->second];
        if (l.type == Type::String && l.dimensions.empty()) {
          program_->refs.push_back(VarRef{true, it->second, l.offset, kNone, 0});
          item.name_format = std::uint32_t(program_->refs.size() - 1);
        }
      } else if (auto gid = lookup_global(format_name)) {
        const GlobalVariable& v = program_->globals[*gid];
        if (v.typed && v.type == Type::String && v.dimensions.empty()) {
          program_->refs.push_back(VarRef{false, *gid, v.first_cell, kNone, 0});
          item.name_format = std::uint32_t(program_->refs.size() - 1);
        }
      }
    }
  } else {
    item.a = expression(operand, ctx);
  }
  if (n.children.size() > 1) {
    const SyntaxNode& spec = *n.children[1]->children[0];
    if (spec.is_type<g::string_literal>()) {
      std::string text = literal_text(spec, ctx.file);
      try {
        (void)parse_display_format(text);
      } catch (const Error& e) {
        // Checked when used, as GPPTool does (5.3); flagged now so the post writer sees it early.
        warn(node_pos(spec, ctx.file), fmt::format("display format '{}' is invalid ({}): error {} when used", text,
                                                    e.text(), e.number()));
      }
      item.format_kind = FormatKind::Constant;
      program_->format_specs.push_back(std::move(text));
      item.format = std::uint32_t(program_->format_specs.size() - 1);
    } else {
      item.format_kind = FormatKind::Dynamic;
      item.format = expression(spec, ctx);
    }
  }
  items.push_back(item);
}

std::optional<LineFunction> Compiler::line_function_of(const SyntaxNode& operand) const {
  if (!operand.is_type<g::variable>() || operand.children.size() != 1) return std::nullopt;
  return line_function_named(operand.children[0]->string_view());
}

std::optional<LineFunction> line_function_named(std::string_view name) {
  if (same_name(name, "start_line")) return LineFunction::StartLine;
  if (same_name(name, "end_line")) return LineFunction::EndLine;
  return std::nullopt;
}

void Compiler::collect_refs(std::uint32_t node, std::vector<std::uint32_t>& out) const {
  const Node& n = program_->nodes[node];
  switch (n.kind) {
    case NodeKind::Constant: return;
    case NodeKind::Variable:
    case NodeKind::Attribute: out.push_back(n.a); return;
    case NodeKind::Negate:
    case NodeKind::Not: collect_refs(n.a, out); return;
    case NodeKind::Binary:
    case NodeKind::And:
    case NodeKind::Or:
      collect_refs(n.a, out);
      collect_refs(n.b, out);
      return;
    case NodeKind::Call:
      for (std::uint32_t i = 0; i < n.count; ++i) collect_refs(program_->lists[n.list + i], out);
      return;
  }
}

}  // namespace gppl
