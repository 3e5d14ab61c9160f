// Directives other than control flow: #declare #local #undef #include #version #debug
// #warning #error #default (and #macro, in macros.cpp). They run inside settle(), so item
// parsers never see them.
#include <algorithm>
#include <optional>
#include <string>

#include "sdl/diagnostics.hpp"
#include "sdl/items.hpp"
#include "sdl/parser_impl.hpp"
#include "util/printable.hpp"

namespace convray::sdl {
namespace {

constexpr std::string_view kDirectiveNames[] = {
    "break",      "case",    "debug",  "declare", "default", "else",  "elseif",
    "end",        "error",   "fclose", "fopen",   "for",     "if",    "ifdef",
    "ifndef",     "include", "local",  "macro",   "range",   "read",  "render",
    "statistics", "switch",  "undef",  "version", "warning", "while", "write"};

}  // namespace

void Parser::Impl::run_directive() {
  const LexToken& t = plain();
  const TokenRef at = ref();
  const std::uint32_t index = frames.back().pos;
  const Word word = t.word;
  advance();
  switch (word) {
    case Word::declare:
      directive_declare(false, at);
      return;
    case Word::local:
      directive_declare(true, at);
      return;
    case Word::undef:
      directive_undef();
      return;
    case Word::include:
      directive_include(at);
      return;
    case Word::version: {
      const TokenRef value_at = ref();
      language_version = to_float(parse_expression(), value_at, "after #version");
      version_given = true;
      accept_optional_semicolon();
      return;
    }
    case Word::debug:
    case Word::warning:
    case Word::render:
    case Word::statistics:
    case Word::error:
      directive_message(word, at);
      return;
    case Word::default_:
      directive_default();
      return;
    case Word::if_:
    case Word::ifdef:
    case Word::ifndef:
      directive_if(word, index);
      return;
    case Word::else_:
    case Word::elseif:
      directive_else(word, at);
      return;
    case Word::while_:
      directive_while(index);
      return;
    case Word::for_:
      directive_for(index);
      return;
    case Word::switch_:
      directive_switch(index);
      return;
    case Word::case_:
    case Word::range:
      directive_case(word, at);
      return;
    case Word::break_:
      directive_break(at);
      return;
    case Word::end:
      directive_end(at);
      return;
    case Word::macro:
      directive_macro(at);
      return;
    case Word::fopen:
      directive_fopen(at);
      return;
    case Word::fclose:
      directive_fclose(at);
      return;
    case Word::read:
      directive_read(at);
      return;
    case Word::write:
      directive_write(at);
      return;
    default:
      break;
  }
  // Unknown: suggest the closest directive name.
  const std::string name(at.token->view());
  std::string suggestion;
  int best = 3;  // at most two edits away
  for (std::string_view candidate : kDirectiveNames) {
    const int distance = edit_distance(name, candidate);
    if (distance < best) {
      best = distance;
      suggestion = " (did you mean '#" + std::string(candidate) + "'?)";
    }
  }
  fail(at, "unknown directive '#" + name + "'" + suggestion);
}

void Parser::Impl::accept_optional_semicolon() {
  if (plain_symbol(';')) advance();
}

Value Parser::Impl::parse_rvalue() {
  NestingLevel level(*this);
  const LexToken& t = settle();
  if (t.word == Word::array) return parse_array_declaration();
  Value item;
  bool is_item = false;
  const std::optional<UnsupportedItem> unsupported =
      owner.parse_or_skip_unsupported([&] { is_item = parse_item(owner, item); });
  if (unsupported) {
    // Once per feature: include files declare dozens of such items.
    const std::string text =
        unsupported->feature + ": items declared with it are accepted, using one is an error";
    const bool told = std::any_of(warnings.begin(), warnings.end(), [&](const std::string& w) {
      return w.find(text) != std::string::npos;
    });
    if (!told) warn(unsupported->feature_at, text);
    item.data = std::make_shared<const UnsupportedItem>(*unsupported);
    return item;
  }
  if (is_item) return item;
  return parse_expression();
}

void Parser::Impl::directive_declare(bool local, TokenRef) {
  const std::string directive = local ? "#local" : "#declare";
  // POV-Ray 3.7: `#declare deprecated [once] "message" Name = ...`.
  std::optional<Deprecation> deprecation;
  if (plain().word == Word::deprecated) {
    advance();
    Deprecation d;
    if (plain().word == Word::once) {
      d.once = true;
      advance();
    }
    const TokenRef message_at = ref();
    d.message = to_string(parse_expression(), message_at, "after 'deprecated'");
    deprecation = std::move(d);
  }
  const TokenRef name_at = ref();
  const std::string name(expect_identifier_raw("after " + directive));
  const std::uint64_t scope = local ? scopes.back().serial : scopes.front().serial;

  if (plain_symbol('[')) {
    // Element assignment: #declare A[i][j] = value.
    std::vector<std::size_t> path;
    {
      const Value* root = lookup(name);
      if (root == nullptr)
        fail(name_at, "undeclared identifier '" + name + "'" + did_you_mean(name));
      path = parse_element_path(*root, name);
    }
    if (!plain_symbol('='))
      fail_here("expected '=' after " + directive + " " + name + "[...]" + ", found " +
                describe(plain()));
    advance();
    Value value = parse_rvalue();
    Value* root = lookup(name);
    if (root == nullptr)
      fail(name_at, "'" + name + "' was undeclared while its value was computed");
    store_element(*root, path, std::move(value), name, name_at);
    accept_optional_semicolon();
    return;
  }

  if (!plain_symbol('=')) {
    fail_here("expected '=' after " + directive + " " + name + ", found " + describe(plain()));
  }
  advance();
  if (settle().word == Word::function) {
    declare_function(name);
    accept_optional_semicolon();
    return;
  }
  Value value = parse_rvalue();
  value.loc = loc(name_at);
  if (const Alias* alias = innermost_alias(name)) {
    // A macro parameter passed by reference: #declare and #local both assign the caller's
    // variable, as in POV-Ray.
    const Alias target = *alias;
    store_through(target, std::move(value), name_at);
  } else {
    store(scope, name, std::move(value));
  }
  if (!macros.empty()) macros.erase(name);
  if (!functions.empty()) functions.erase(name);
  if (deprecation) deprecations[name] = std::move(*deprecation);
  accept_optional_semicolon();
  if (const Value* stored = lookup(name);
      stored && (stored->get<std::shared_ptr<const scene::Texture>>() ||
                 stored->get<std::shared_ptr<const UnsupportedItem>>())) {
    last_texture_name = name;
    last_texture_end = tokens_read;
  }
}

Value* Parser::Impl::texture_declared_just_before() {
  if (last_texture_end != tokens_read) return nullptr;
  return lookup(last_texture_name);
}

bool Parser::texture_declared_just_before() {
  return impl_->texture_declared_just_before() != nullptr;
}

void Parser::add_declared_texture_layer(const std::optional<scene::Texture>& layer,
                                        const std::optional<UnsupportedItem>& unsupported) {
  // Called after the layer was read: the declaration is the one texture_declared_just_before
  // found, and the next layer may follow this one.
  Value* declared = impl_->lookup(impl_->last_texture_name);
  impl_->last_texture_end = impl_->tokens_read;
  if (declared == nullptr) return;
  const auto* texture = declared->get<std::shared_ptr<const scene::Texture>>();
  if (texture == nullptr || !*texture) return;  // unusable already
  if (unsupported) {
    declared->data = std::make_shared<const UnsupportedItem>(*unsupported);
  } else if (layer) {
    declared->data = std::make_shared<const scene::Texture>(scene::layered_on(**texture, *layer));
  }
}

void Parser::Impl::directive_undef() {
  const TokenRef at = ref();
  const std::string_view name = expect_identifier_raw("after #undef");
  if (!undeclare(name))
    warn(loc(at), "#undef of '" + std::string(name) + "', which is not declared");
}

void Parser::Impl::directive_include(TokenRef at) {
  const TokenRef name_at = ref();
  std::string name;
  {
    // The file that includes stays open while the name is read, even when the #include is
    // its last line: a file that includes itself must count as nesting.
    ScopedValue hold(frame_floor, int(frames.size()));
    name = to_string(parse_expression(), name_at, "after #include");
  }
  if (include_depth >= options.max_include_depth) {
    fail(at, "#include nested more than " + std::to_string(options.max_include_depth) +
                 " levels deep (does a file include itself?)");
  }
  const std::string path = resolve(name, loc(name_at), true);
  const SourceFile& file = load_file(path, loc(name_at));
  const std::uint64_t scope = push_scope();
  Frame& frame = push_frame(Frame::Kind::include, &file, 0, std::uint32_t(file.tokens.size() - 1));
  frame.scope = scope;
  ++include_depth;
}

void Parser::Impl::directive_message(Word kind, TokenRef at) {
  const TokenRef text_at = ref();
  std::string text = to_string(parse_expression(), text_at, "after the directive");
  if (kind == Word::error) fail(at, text);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (kind == Word::warning) {
    warn(loc(at), text);
  } else {
    // Scene text reaches the terminal escaped (no raw escape sequences), long runs cut.
    warnings.push_back(
        printable(loc(at).str() + ": #" + std::string(at.token->view()) + ": " + text));
  }
}

void Parser::Impl::directive_default() {
  expect_symbol('{', "after #default");
  while (!accept_symbol('}')) {
    const TokenRef at = ref();
    Value item;
    if (!parse_item(owner, item)) {
      fail_here("expected texture, pigment, finish or normal in #default, found " +
                describe(settle()));
    }
    scene::Texture& texture = defaults.texture;
    if (const auto* t = item.get<std::shared_ptr<const scene::Texture>>()) {
      texture = **t;
    } else if (const auto* p = item.get<std::shared_ptr<const scene::Pigment>>()) {
      texture.pigment = **p;
    } else if (const auto* f = item.get<std::shared_ptr<const scene::Finish>>()) {
      texture.finish = **f;
    } else if (const auto* n = item.get<std::shared_ptr<const scene::Normal>>()) {
      texture.normal = **n;
    } else {
      fail(at, "#default takes a texture, pigment, finish or normal, found " + type_name(item));
    }
  }
}

}  // namespace convray::sdl
