// Declarations: the script's shape, constants, types, variables and routines (spec 2.2, 2.3, 5).
#include "machines/pikocnc/script/compile_support.hpp"

namespace pikocnc::script {

namespace g = grammar;

std::string_view token(const Node& node) {
  const std::string_view s = node.string_view();
  auto word = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; };
  std::size_t n = 0;
  if (!s.empty() && word(s[0])) {
    while (n < s.size() && word(s[n])) ++n;
  } else if (s.size() >= 2 && (s.substr(0, 2) == "<>" || s.substr(0, 2) == "<=" || s.substr(0, 2) == ">=" || s.substr(0, 2) == ":=")) {
    n = 2;
  } else {
    n = s.empty() ? 0 : 1;
  }
  return s.substr(0, n);
}

std::string fold(std::string_view name) {
  std::string out(name);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
  return out;
}

std::string type_name(const Program& program, const Type& type) {
  switch (type.kind) {
    case Kind::Integer: return type.width == 1 ? "Byte" : type.width == 2 ? "Cardinal" : "Integer";
    case Kind::Float: return "Extended";
    case Kind::Boolean: return "Boolean";
    case Kind::String: return "String";
    case Kind::Variant: return "Variant";
    case Kind::Void: return "no value";
    case Kind::Record: return program.shapes[std::size_t(type.shape)].name;
    case Kind::Array: {
      const Shape& s = program.shapes[std::size_t(type.shape)];
      return fmt::format("array[{}..{}] of {}", s.low, s.low + s.count - 1, type_name(program, s.element));
    }
  }
  return "?";
}

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Integer: return "Integer";
    case Kind::Float: return "Extended";
    case Kind::Boolean: return "Boolean";
    case Kind::String: return "String";
    case Kind::Variant: return "Variant";
    case Kind::Record: return "record";
    case Kind::Array: return "array";
    case Kind::Void: return "no value";
  }
  return "?";
}

void Compiler::fail(const Node& at, const std::string& message) const { fail(pos(at), message); }
void Compiler::fail(Pos at, const std::string& message) const {
  throw toolpath::InputError({file_, at.line, at.column}, message);
}

const Symbol* Compiler::lookup(std::string_view folded) const {
  const std::string key(folded);
  if (current_) {
    if (auto it = locals_.find(key); it != locals_.end()) return &it->second;
  }
  if (auto it = globals_.find(key); it != globals_.end()) return &it->second;
  return nullptr;
}

void Compiler::declare(const Node& name, Symbol symbol, bool global) {
  const std::string key = fold(token(name));
  auto& scope = global ? globals_ : locals_;
  if (scope.count(key)) fail(name, fmt::format("`{}` is already declared", token(name)));
  // Built-in routines may be shadowed (the document's own example declares `ln: TLine`), the
  // predefined constants may not: a script redefining MAT_SIZE_X is surely a mistake.
  if (find_predefined(key) >= 0)
    fail(name, fmt::format("`{}` is a predefined constant and cannot be redeclared", token(name)));
  scope.emplace(key, symbol);
}

std::unique_ptr<Program> Compiler::compile(const Node& root) {
  program_ = std::make_unique<Program>();
  program_->file = file_;
  const Type ext{Kind::Float};
  program_->shapes.push_back({"TPoint", {"x", "y"}, {ext, ext}, {}, 0, 0});
  const Type point{Kind::Record, 0, kTPoint};
  program_->shapes.push_back({"TLine", {"s", "e"}, {point, point}, {}, 0, 0});
  auto basic = [&](const char* n, Type t) { globals_.emplace(n, Symbol{Symbol::What::TypeName, 0, t, false}); };
  basic("integer", {Kind::Integer});
  basic("longint", {Kind::Integer});
  basic("byte", {Kind::Integer, 1});
  basic("cardinal", {Kind::Integer, 2});
  basic("word", {Kind::Integer, 2});
  for (const char* n : {"extended", "double", "single", "real"}) basic(n, {Kind::Float});
  basic("boolean", {Kind::Boolean});
  basic("string", {Kind::String});
  basic("variant", {Kind::Variant});
  basic("tpoint", point);
  basic("tline", {Kind::Record, 0, kTLine});

  for (const auto& child : root.children) {
    const Node& n = *child;
    if (is<g::program_head>(n)) continue;
    if (is<g::routine>(n)) routine(n);
    else if (is<g::main_block>(n)) program_->main = statements(*n.children.front()->children.front(), St::Block);
    else if (is<g::fragment>(n)) program_->main = statements(*n.children.front(), St::Block);
    else declarations(n, true);
  }
  if (!program_->main) program_->main = std::make_unique<Stmt>();
  return std::move(program_);
}

Type Compiler::type_of(const Node& node) {
  if (is<g::type_name>(node) || is<g::ident>(node)) {
    const Symbol* s = lookup(fold(token(node)));
    if (!s || s->what != Symbol::What::TypeName) fail(node, fmt::format("unknown type `{}`", token(node)));
    return s->type;
  }
  if (is<g::result_type>(node)) return type_of(*node.children.front());
  if (is<g::record_type>(node)) {
    Shape shape;
    shape.name = "record";
    for (const auto& field : node.children) {
      const Type t = type_of(*field->children.back());
      for (const auto& name : field->children.front()->children) {
        const std::string key = fold(token(*name));
        for (const auto& f : shape.fields)
          if (f == key) fail(*name, fmt::format("field `{}` is declared twice", token(*name)));
        shape.fields.push_back(key);
        shape.field_types.push_back(t);
      }
    }
    program_->shapes.push_back(std::move(shape));
    return {Kind::Record, 0, std::int32_t(program_->shapes.size() - 1)};
  }
  if (is<g::array_type>(node)) {
    if (node.children.size() < 2) fail(node, "an array needs bounds: array[low..high] of T");
    const Node& range = *node.children.front();
    auto bound = [&](const Node& e) -> std::int64_t {
      auto x = expr(e);
      if (x->op != Op::Literal || x->literal.kind != Kind::Integer)
        fail(e, "an array bound must be an integer literal or constant");
      return x->literal.i;
    };
    const std::int64_t low = bound(*range.children[0]), high = bound(*range.children[1]);
    if (high < low || high - low >= 1'000'000) fail(range, fmt::format("bad array bounds {}..{} (at most 1000000 elements)", low, high));
    Shape shape;
    shape.name = "array";
    shape.element = type_of(*node.children.back());
    if (double(high - low + 1) * double(value_count(shape.element)) > 1e6)
      fail(range, "array too large: at most 1000000 values in all (records count each field)");
    shape.low = low;
    shape.count = high - low + 1;
    program_->shapes.push_back(std::move(shape));
    return {Kind::Array, 0, std::int32_t(program_->shapes.size() - 1)};
  }
  fail(node, "expected a type");
}

std::int64_t Compiler::value_count(const Type& t) const {
  if (t.kind == Kind::Record) {
    std::int64_t n = 0;
    for (const auto& f : program_->shapes[std::size_t(t.shape)].field_types) n += value_count(f);
    return n;
  }
  if (t.kind == Kind::Array) {
    const Shape& s = program_->shapes[std::size_t(t.shape)];
    return s.count * value_count(s.element);
  }
  return 1;
}

void Compiler::declarations(const Node& section, bool global) {
  auto& slots = global ? program_->globals : current_->locals;
  auto& inits = global ? program_->const_inits : current_->const_inits;
  for (const auto& d : section.children) {
    if (is<g::var_decl>(*d)) {
      const Type t = type_of(*d->children.back());
      for (const auto& name : d->children.front()->children) {
        // Locals are made anew on every call, recursive ones too: keep them small.
        if (!global && value_count(t) > 10'000)
          fail(*name, "a local variable may hold at most 10000 values: declare a large array globally");
        declare(*name, {Symbol::What::Var, std::int32_t(slots.size()), t, false}, global);
        slots.push_back(t);
      }
    } else if (is<g::type_def>(*d)) {
      const Type t = type_of(*d->children.back());
      if (t.kind == Kind::Record && program_->shapes[std::size_t(t.shape)].name == "record")
        program_->shapes[std::size_t(t.shape)].name = std::string(token(*d->children.front()));
      declare(*d->children.front(), {Symbol::What::TypeName, 0, t, false}, global);
    } else if (is<g::const_def>(*d)) {
      auto value = expr(*d->children.back());
      if (value->type.kind == Kind::Void) fail(*d->children.back(), "a constant needs a value");
      const std::int32_t slot = std::int32_t(slots.size());
      slots.push_back(value->type);
      // Literal constants fold, so they can size arrays; others are computed when the script starts.
      declare(*d->children.front(), {Symbol::What::Const, slot, value->type, false}, global);
      if (value->op == Op::Literal) folded_[global ? 0 : 1].emplace(fold(token(*d->children.front())), value->literal);
      inits.emplace_back(slot, std::move(value));
    }
  }
}

void Compiler::routine(const Node& node) {
  const Node& head = *node.children.front();
  const Node& name = *head.children.front();
  const bool is_function = is<g::func_head>(head);
  Routine r;
  r.name = std::string(token(name));
  r.pos = pos(name);
  r.is_function = is_function;
  const std::int32_t index = std::int32_t(program_->routines.size());
  locals_.clear();
  folded_[1].clear();
  current_ = &r;
  current_index_ = index;
  if (is_function) {
    r.result = type_of(*head.children.back());
    r.locals.push_back(r.result);
    r.first_param = 1;
    locals_.emplace("result", Symbol{Symbol::What::Var, 0, r.result, false});
  }
  for (std::size_t i = 1; i < head.children.size(); ++i) {
    if (!is<g::params>(*head.children[i])) continue;
    for (const auto& param : head.children[i]->children) {
      const bool by_ref = is<g::by_ref>(*param->children.front());
      const Type t = type_of(*param->children.back());
      const Node& names = *param->children[is<g::by_ref>(*param->children.front()) || is<g::by_const>(*param->children.front()) ? 1 : 0];
      for (const auto& n : names.children) {
        const std::string key = fold(token(*n));
        if (locals_.count(key)) fail(*n, fmt::format("parameter `{}` is declared twice", token(*n)));
        locals_.emplace(key, Symbol{Symbol::What::Var, std::int32_t(r.locals.size()), t, by_ref});
        r.locals.push_back(t);
        r.params.push_back(t);
        r.by_ref.push_back(by_ref);
      }
    }
  }
  // Declared before its body so that it can call itself.
  declare(name, {Symbol::What::Routine, index, r.result, false}, true);
  program_->routines.push_back(std::move(r));
  Routine& placed = program_->routines.back();
  current_ = &placed;
  for (std::size_t i = 1; i + 1 < node.children.size(); ++i) declarations(*node.children[i], false);
  placed.body = statements(*node.children.back()->children.front(), St::Block);
  placed.defined = true;
  current_ = nullptr;
  current_index_ = -1;
  locals_.clear();
}

}  // namespace pikocnc::script
