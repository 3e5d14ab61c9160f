// Parser's public API over Parser::Impl (parser_impl.hpp), and the context every part of
// the parse shares: files, messages, include search.
#include "sdl/parser.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sdl/diagnostics.hpp"
#include "sdl/items.hpp"
#include "sdl/keywords.hpp"
#include "sdl/parse_log.hpp"
#include "sdl/parser_impl.hpp"
#include "util/file_kind.hpp"
#include "util/printable.hpp"

namespace convray::sdl {

bool read_file(const std::string& path, std::string& text) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream stream(path, std::ios::binary);
  if (!stream) return false;
  std::ostringstream contents;
  contents << stream.rdbuf();
  text = std::move(contents).str();
  return !stream.bad();
}

namespace {

// Declare=ID=VALUE from the command line names an identifier. A name that is not one is
// refused; a reserved word is shadowed by the keyword in every use, so POV-Ray accepts it and
// nothing can read it: convray accepts it too, and says so (`warning`, returned).
std::optional<std::string> check_declared_name(const std::string& name) {
  const SourceLoc where{"command line"};
  const bool letters = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) ||
                                         name[0] == '_');
  const bool word = std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
  if (!letters || !word) {
    throw InputError(where, "Declare=" + name + ": '" + name +
                                "' is not an identifier (a letter or _, then letters, digits, _)");
  }
  if (classify_word(name) != Word::none) {
    return "Declare=" + name + ": '" + name +
           "' is a reserved word of the scene language, so the scene cannot read this "
           "declaration (POV-Ray ignores it too); ignored";
  }
  return std::nullopt;
}

}  // namespace

// --- Impl: context ------------------------------------------------------------------------

Parser::Impl::Impl(Parser& owner_parser, ParseOptions parse_options)
    : owner(owner_parser), options(std::move(parse_options)) {
  push_scope();  // the global scope
  for (const auto& [name, value] : options.declares) {
    if (const std::optional<std::string> warning = check_declared_name(name)) {
      warn(SourceLoc{"command line"}, *warning);
      continue;
    }
    declare_global(name, make_value(value));
  }
}

void Parser::Impl::fail(const SourceLoc& at, const std::string& message) const {
  const auto file = files_by_name.find(at.file);
  if (file == files_by_name.end()) throw InputError(at, message);
  throw InputError(at, with_source_line(message, file->second->text, at.line, at.column));
}

void Parser::Impl::warn(const SourceLoc& at, const std::string& message) {
  const auto file = files_by_name.find(at.file);
  const std::string text = file == files_by_name.end()
                               ? message
                               : with_source_line(message, file->second->text, at.line, at.column);
  warnings.push_back(printable(at.str() + ": " + text));
}

void Parser::Impl::enter_nesting() {
  if (++nesting_depth > kMaxNestingDepth) {
    --nesting_depth;
    fail_here("nested more than " + std::to_string(kMaxNestingDepth) +
              " levels deep (expressions, items or directives)");
  }
}

std::string Parser::Impl::resolve(const std::string& name, const SourceLoc& at,
                                  bool must_exist) const {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path given(name);
  std::vector<fs::path> folders;
  if (given.is_absolute()) {
    folders.emplace_back();
  } else {
    // The folder of the file being read, then +L paths, then POV-Ray's installed includes.
    const fs::path current = fs::path(frames.empty() ? std::string() : frames.back().file->name);
    folders.push_back(current.parent_path());
    for (const std::string& folder : options.library_paths) folders.emplace_back(folder);
    for (const std::string& folder : options.system_include_paths) folders.emplace_back(folder);
  }
  for (const fs::path& folder : folders) {
    const fs::path candidate = folder.empty() ? given : folder / given;
    const fs::file_status status = fs::status(candidate, error);
    if (error.value() == ELOOP) {
      if (!must_exist) return {};
      fail(at, "cannot read '" + name + "': " + candidate.string() +
                   " is a loop of symbolic links");
    }
    if (!fs::exists(status)) continue;
    if (!readable.allows(candidate.string())) {
      if (!must_exist) return {};  // file_exists() says no, as for a missing file
      fail(at, "cannot read '" + name + "': it is outside the folders a scene may read (" +
                   allowed_folders_text() +
                   "; POV-Ray's I/O restrictions); convray --allow-read FOLDER widens them");
    }
    if (fs::is_regular_file(status)) {
      std::string found = candidate.lexically_normal().string();
      if (options.log) options.log->note_file(found);
      return found;
    }
    if (!must_exist) return {};
    fail(at, "cannot read '" + name + "': " + candidate.string() + " is " +
                 describe_file_kind(status) + ", not a file");
  }
  if (!must_exist) return {};
  if (options.log) {  // where it would have been found: creating it there fixes the scene
    for (const fs::path& folder : folders) {
      options.log->note_file((folder.empty() ? given : folder / given).lexically_normal().string());
    }
  }
  std::string searched;
  for (const fs::path& folder : folders) {
    searched += searched.empty() ? "" : ", ";
    searched += folder.empty() ? std::string(".") : folder.string();
  }
  fail(at, "file not found: '" + name + "' (searched " + searched + ")");
}

std::string Parser::Impl::allowed_folders_text() const {
  std::string text = "the scene's folder, the working folder, +L library paths, POV-Ray's "
                     "include folder and the output folder: ";
  const std::vector<std::string>& folders = readable.folders();
  for (size_t i = 0; i < folders.size(); ++i) text += (i ? ", " : "") + folders[i];
  return text;
}

void Parser::Impl::allow_reads_for(const std::string& scene_name) {
  if (options.read_anywhere) readable.allow_anywhere();
  readable.allow(std::filesystem::path(scene_name).parent_path().string());
  readable.allow(".");
  for (const std::string& folder : options.library_paths) readable.allow(folder);
  for (const std::string& folder : options.system_include_paths) {
    readable.allow_with_links(folder);
  }
  for (const std::string& folder : options.read_folders) readable.allow(folder);
}

const SourceFile& Parser::Impl::load_file(const std::string& path, const SourceLoc& at) {
  if (const auto loaded = files_by_name.find(path); loaded != files_by_name.end()) {
    return *loaded->second;
  }
  std::string text;
  if (!read_file(path, text)) fail(at, "cannot read '" + path + "'");
  std::unique_ptr<SourceFile> file = tokenize(path, std::move(text));
  for (std::string& warning : file->warnings) warnings.push_back(std::move(warning));
  file->warnings.clear();
  const SourceFile& loaded = *file;
  files_by_name.emplace(path, file.get());
  files.push_back(std::move(file));
  return loaded;
}

// --- Parser -------------------------------------------------------------------------------

Parser::Parser(std::string file_name, std::string text, ParseOptions options)
    : impl_(std::make_unique<Impl>(*this, std::move(options))) {
  std::unique_ptr<SourceFile> file = tokenize(std::move(file_name), std::move(text));
  Impl& impl = *impl_;
  impl.allow_reads_for(file->name);
  // After the command line's (Declare=), the lexer's.
  for (std::string& warning : file->warnings) impl.warnings.push_back(std::move(warning));
  file->warnings.clear();
  impl.files_by_name.emplace(file->name, file.get());
  const SourceFile& scene = *file;
  impl.files.push_back(std::move(file));
  impl.push_frame(Frame::Kind::scene, &scene, 0, std::uint32_t(scene.tokens.size() - 1));
}

Parser::~Parser() = default;

scene::Scene Parser::parse_scene() {
  scene::Scene scene;
  while (impl_->settle().kind != LexKind::end) {
    const long long before = impl_->tokens_read;
    parse_statement(*this, scene);
    if (impl_->tokens_read == before) {
      impl_->fail_here("expected a statement, found " + impl_->describe(impl_->settle()));
    }
  }
  impl_->close_open_files();
  apply_legacy_gamma(scene);
  scene.settings.language_version = impl_->version_given ? impl_->language_version : 3.62;
  for (const auto& action : impl_->parse_end_actions) action(scene);
  return scene;
}

// POV-Ray 3.7's rule, as its binary shows: a scene without assumed_gamma whose language
// version, when the parse ends, is below 3.7 (or that never said #version: include files
// that set and restore #version count as saying it) is rendered without gamma correction,
// with this warning (POV-Ray's words).
void Parser::apply_legacy_gamma(scene::Scene& scene) {
  if (impl_->assumed_gamma_given) return;
  if (impl_->version_given && impl_->language_version >= 3.7 - 1e-9) return;
  scene.settings.gamma_correction = false;
  impl_->warn(SourceLoc{impl_->files.front()->name},
              "assumed_gamma not specified, so gamma_correction is turned off for "
              "compatibility with this pre POV-Ray 3.7 scene (as in POV-Ray 3.7: colours are "
              "written as computed, without the sRGB encoding)");
}

void Parser::note_assumed_gamma() { impl_->assumed_gamma_given = true; }

void Parser::at_parse_end(std::function<void(const scene::Scene&)> action) {
  impl_->parse_end_actions.push_back(std::move(action));
}

const Token& Parser::peek() { return impl_->materialize(); }

Token Parser::next() {
  Token token = impl_->materialize();
  impl_->advance();
  return token;
}

bool Parser::at(std::string_view text) {
  const LexToken& t = impl_->settle();
  return (t.kind == LexKind::keyword || t.kind == LexKind::symbol) && t.view() == text;
}

bool Parser::accept(std::string_view text) {
  if (!at(text)) return false;
  impl_->advance();
  return true;
}

Token Parser::expect(std::string_view text, std::string_view what) {
  if (at(text)) return next();
  // "in sphere"; a `what` that starts with its own preposition ("to close sphere ...") is
  // used as it is.
  static constexpr std::string_view kPrepositions[] = {"to ",  "in ", "after ",   "before ",
                                                       "for ", "at ", "between ", "of "};
  std::string context(what);
  bool has_preposition = false;
  for (std::string_view preposition : kPrepositions) {
    has_preposition = has_preposition || what.substr(0, preposition.size()) == preposition;
  }
  if (!context.empty() && !has_preposition) context = "in " + context;
  impl_->fail_here("expected '" + std::string(text) + "'" + (context.empty() ? "" : " ") + context +
                   ", found " + impl_->describe(impl_->settle()));
}

Value Parser::parse_expression() { return impl_->parse_expression(); }

double Parser::parse_float() {
  impl_->settle();
  const TokenRef at = impl_->ref();
  return impl_->to_float(impl_->parse_expression(), at, "");
}

double Parser::parse_float_in_angle_brackets() {
  ScopedValue in_vector(impl_->angle_depth, 1);
  return parse_float();
}

int Parser::parse_int() {
  impl_->settle();
  const TokenRef at = impl_->ref();
  const double value = impl_->to_float(impl_->parse_expression(), at, "");
  return impl_->to_int(value, at, "");
}

Vec3 Parser::parse_vector() {
  impl_->settle();
  const TokenRef at = impl_->ref();
  const Value value = impl_->parse_expression();
  if (const double* f = value.get<double>()) return Vec3(*f);
  if (const Vector* vector = value.get<Vector>()) return vector->xyz();
  impl_->fail(at, "expected a vector, found " + type_name(value));
}

scene::Color Parser::parse_color() {
  impl_->settle();
  const TokenRef at = impl_->ref();
  Value value = impl_->parse_expression();
  Vector color;
  if (const double* f = value.get<double>()) {
    color.v = {*f, *f, *f, 0.0, 0.0};
  } else if (const Vector* vector = value.get<Vector>()) {
    color = *vector;
  } else {
    impl_->fail(at, "expected a colour, found " + type_name(value));
  }
  // Modifiers after a float or vector used as a colour: `pigment { 0.5 filter 0.2 }`.
  const Value modified = impl_->apply_color_modifiers(make_value(Impl::to_color(color)));
  return modified.get<Vector>()->as_color();
}

double Parser::parse_float_before_points() {
  ScopedValue points_follow(impl_->less_starts_vector, 1);
  return parse_float();
}

Vec3 Parser::parse_vector_before_points() {
  ScopedValue points_follow(impl_->less_starts_vector, 1);
  return parse_vector();
}

std::string Parser::parse_string() {
  impl_->settle();
  const TokenRef at = impl_->ref();
  return impl_->to_string(impl_->parse_expression(), at, "");
}

const Value* Parser::peek_declared() {
  const LexToken& t = impl_->settle();
  if (t.kind != LexKind::identifier) return nullptr;
  const Value* value = impl_->lookup(t.view());
  if (value != nullptr && !impl_->deprecations.empty()) {
    impl_->check_deprecated(t.view(), impl_->ref());
  }
  if (value != nullptr) impl_->check_usable(*value, t.view(), impl_->ref());
  return value;
}

const ParseOptions& Parser::options() const { return impl_->options; }
Defaults& Parser::defaults() { return impl_->defaults; }

std::string Parser::resolve_file(const std::string& name, const SourceLoc& loc) const {
  return impl_->resolve(name, loc, true);
}

std::string Parser::resolve_file(const std::string& name, const SourceLoc& loc,
                                 const std::string& file_type) const {
  if (std::string found = impl_->resolve(name, loc, false); !found.empty()) return found;
  if (std::string typed = impl_->resolve(name + file_type, loc, false); !typed.empty()) {
    return typed;
  }
  return impl_->resolve(name, loc, true);  // fails, saying where it looked
}

void Parser::count_mesh_elements(ElementCount& held, std::size_t count, const SourceLoc& loc) {
  impl_->recount_elements(held, count, loc);
}

void Parser::check_element_budget(std::size_t more, const SourceLoc& loc) const {
  impl_->check_element_budget(more, loc);
}

void Parser::fail(const SourceLoc& loc, const std::string& message) const {
  impl_->fail(loc, message);
}

void Parser::fail_here(const std::string& message) {
  impl_->settle();
  impl_->fail_here(message);
}

void Parser::warn(const SourceLoc& loc, const std::string& message) { impl_->warn(loc, message); }

const std::vector<std::string>& Parser::warnings() const { return impl_->warnings; }

const std::map<std::string, Value>& Parser::globals() const {
  std::map<std::string, Value>& view = impl_->globals_view;
  view.clear();
  for (const auto& [name, value] : impl_->scopes.front().values) view.emplace(name, value);
  return view;
}

std::string Parser::did_you_mean(std::string_view name) const { return impl_->did_you_mean(name); }

Parser::NestingGuard::NestingGuard(Parser& parser) : parser_(parser) {
  parser_.impl_->enter_nesting();
}

Parser::NestingGuard::~NestingGuard() { parser_.impl_->leave_nesting(); }

// --- Whole scenes -------------------------------------------------------------------------

ParseResult parse_file(const std::string& path, const ParseOptions& options) {
  if (const std::optional<std::string> kind = not_a_file(path)) {
    throw InputError({path}, "cannot read the scene file: it " + *kind);
  }
  std::string text;
  if (!read_file(path, text)) throw InputError({path}, "cannot read the scene file");
  return parse_string(text, path, options);
}

ParseResult parse_string(const std::string& text, const std::string& name,
                         const ParseOptions& options) {
  Parser parser(name, text, options);
  ParseResult result;
  result.scene = parser.parse_scene();
  result.globals = parser.globals();
  result.warnings = parser.warnings();
  return result;
}

}  // namespace convray::sdl
