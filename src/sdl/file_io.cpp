// POV-Ray's file directives: `#fopen NAME "file" read | write | append`, `#write (NAME, ...)`,
// `#read (NAME, ID, ...)`, `#fclose NAME`. As the povray binary does (checked by
// tests/app/povray_file_io_test.cpp):
//   - #write writes strings as they are, floats as C's %g, vectors as <%g,%g,...> and a space;
//   - #read reads comma-separated quoted strings, floats and <vectors> and #declares the
//     identifiers; at the end of the file it closes the file, whose name is then undefined
//     (`#while (defined(F))` reads to the end): right after a value that no comma follows,
//     or when no value is left (the identifier keeps its value). Reading a file closed so
//     reads nothing, without an error.
// POV-Ray's I/O restrictions: a file is written only in the output image's folder (where a
// relative name goes) or the scene's folder, each with what lies below it; it is read from
// the folders a scene may read (Parser::Impl::resolve), the output folder first. What a scene
// writes reaches the disk whole at #fclose (or the end of the parse), by util::AtomicFile.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <filesystem>

#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"
#include "util/atomic_file.hpp"

namespace convray::sdl {

namespace {

namespace fs = std::filesystem;

std::string g_format(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// Whether `path` lies in `folder` or below it (both made absolute, links resolved where
// they exist).
bool lies_in(const fs::path& path, const fs::path& folder) {
  std::error_code error;
  const fs::path inner = fs::weakly_canonical(path, error);
  if (error) return false;
  const fs::path outer = fs::weakly_canonical(folder.empty() ? fs::path(".") : folder, error);
  if (error) return false;
  auto o = outer.begin();
  auto i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

void skip_separators(const OpenFile& file, std::size_t& pos) {
  while (pos < file.text.size() &&
         (std::isspace(static_cast<unsigned char>(file.text[pos])) || file.text[pos] == ',')) {
    ++pos;
  }
}

// "..." (\" and \\ inside), the text between.
std::optional<Value> read_string(const OpenFile& file, std::size_t& pos, std::string& error) {
  std::string text;
  for (++pos; pos < file.text.size() && file.text[pos] != '"'; ++pos) {
    if (file.text[pos] == '\\' && pos + 1 < file.text.size()) ++pos;
    text += file.text[pos];
  }
  if (pos >= file.text.size()) {
    error = "a string without its closing '\"'";
    return std::nullopt;
  }
  ++pos;
  return make_value(std::move(text));
}

std::optional<double> read_number(const OpenFile& file, std::size_t& pos, std::string& error) {
  const char* begin = file.text.c_str() + pos;
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin) {
    error = "expected a string, a number or a vector at byte " + std::to_string(pos);
    return std::nullopt;
  }
  pos += std::size_t(end - begin);
  return value;
}

// <a, b, ...>: 2 to 5 numbers.
std::optional<Value> read_vector(const OpenFile& file, std::size_t& pos, std::string& error) {
  Vector vector;
  vector.size = 0;
  ++pos;
  while (true) {
    skip_separators(file, pos);
    if (pos < file.text.size() && file.text[pos] == '>') break;
    if (vector.size == 5) {
      error = "a vector of more than 5 components";
      return std::nullopt;
    }
    const std::optional<double> component = read_number(file, pos, error);
    if (!component) return std::nullopt;
    vector.v[size_t(vector.size++)] = *component;
  }
  ++pos;
  if (vector.size < 2) {
    error = "a vector needs at least 2 components";
    return std::nullopt;
  }
  return make_value(vector);
}

std::optional<Value> read_item(OpenFile& file, std::string& error) {
  if (file.text[file.pos] == '"') return read_string(file, file.pos, error);
  if (file.text[file.pos] == '<') return read_vector(file, file.pos, error);
  const std::optional<double> number = read_number(file, file.pos, error);
  if (!number) return std::nullopt;
  return make_value(*number);
}

// The next value of a file being read; nothing (and no error) at its end. `at_end` tells
// that the file ended right after the value, before a comma: POV-Ray closes it then (a
// value followed by "," and the end leaves it open until the next #read finds nothing).
std::optional<Value> read_file_value(OpenFile& file, std::string& error, bool& at_end) {
  skip_separators(file, file.pos);
  if (file.pos >= file.text.size()) return std::nullopt;
  std::optional<Value> value = read_item(file, error);
  if (!value) return std::nullopt;
  while (file.pos < file.text.size() &&
         std::isspace(static_cast<unsigned char>(file.text[file.pos]))) {
    ++file.pos;
  }
  if (file.pos < file.text.size() && file.text[file.pos] == ',') {
    ++file.pos;
  } else {
    at_end = file.pos >= file.text.size();
  }
  return value;
}

}  // namespace

std::string Parser::Impl::writable_path(const std::string& name, TokenRef at) const {
  if (options.write_folder.empty()) {
    fail(at, "#fopen '" + name + "' for writing: this command writes no files");
  }
  const fs::path given(name);
  const fs::path path = given.is_absolute() ? given : fs::path(options.write_folder) / given;
  const fs::path scene_folder = fs::path(files.front()->name).parent_path();
  if (!lies_in(path, options.write_folder) && !lies_in(path, scene_folder)) {
    fail(at, "#fopen '" + name + "' for writing: a scene writes files only in the output " +
                 "folder (" + options.write_folder + ") and its own folder (POV-Ray's I/O " +
                 "restrictions)");
  }
  return path.lexically_normal().string();
}

void Parser::Impl::directive_fopen(TokenRef) {
  const TokenRef name_at = ref();
  const std::string handle(expect_identifier_raw("after #fopen"));
  const TokenRef file_at = ref();
  const std::string name = to_string(parse_expression(), file_at, "as #fopen's file name");
  const LexToken& mode = plain();
  const std::string_view word = mode.view();
  if (word != "read" && word != "write" && word != "append") {
    fail_here("expected read, write or append after #fopen's file name, found " +
              describe(mode));
  }
  advance();
  if (open_files.find(handle) != open_files.end()) {
    fail(name_at, "#fopen: '" + handle + "' is open already (#fclose it first)");
  }
  OpenFile file;
  if (word == "read") {
    const fs::path in_output = fs::path(options.write_folder) / name;
    std::error_code error;
    if (!options.write_folder.empty() && !fs::path(name).is_absolute() &&
        fs::is_regular_file(in_output, error) && readable.allows(in_output.string())) {
      file.path = in_output.string();
    } else {
      file.path = resolve(name, loc(file_at), true);
    }
    if (!read_file(file.path, file.text)) fail(file_at, "cannot read '" + file.path + "'");
  } else {
    file.writing = true;
    file.path = writable_path(name, file_at);
    std::error_code error;
    if (word == "append" && fs::is_regular_file(file.path, error) &&
        !read_file(file.path, file.text)) {
      fail(file_at, "#fopen ... append: cannot read '" + file.path + "'");
    }
  }
  ended_files.erase(handle);
  open_files.emplace(handle, std::move(file));
}

void Parser::Impl::directive_fclose(TokenRef) {
  const std::string handle(expect_identifier_raw("after #fclose"));
  const auto found = open_files.find(handle);
  // Closing a file that #read closed at its end is the usual idiom: nothing to do.
  if (found == open_files.end()) return;
  if (found->second.writing) {
    write_file_atomically(found->second.path, found->second.text, "#write's file");
  }
  open_files.erase(found);
}

void Parser::Impl::close_open_files() {
  for (auto& [handle, file] : open_files) {
    if (file.writing) write_file_atomically(file.path, file.text, "#write's file");
  }
  open_files.clear();
}

void Parser::Impl::directive_write(TokenRef) {
  expect_symbol('(', "after #write");
  const TokenRef handle_at = ref();
  const std::string handle(expect_identifier_raw("in #write"));
  const auto found = open_files.find(handle);
  if (found == open_files.end() || !found->second.writing) {
    fail(handle_at, "#write: '" + handle + "' is not a file opened for writing");
  }
  accept_symbol(',');  // POV-Ray takes `#write (F "text")` too
  std::string text;
  while (!plain_symbol(')')) {
    const TokenRef item_at = ref();
    const Value value = parse_expression();
    if (const std::string* s = value.get<std::string>()) {
      text += *s;
    } else if (const double* f = value.get<double>()) {
      text += g_format(*f);
    } else if (const Vector* v = value.get<Vector>(); v && !v->color) {
      text += "<";
      for (int k = 0; k < v->size; ++k) {
        if (k > 0) text += ',';
        text += g_format(v->v[size_t(k)]);
      }
      text += "> ";  // POV-Ray's trailing space
    } else {
      fail(item_at, "#write writes strings, floats and vectors, found " + type_name(value));
    }
    if (!accept_symbol(',') && !plain_symbol(')')) {
      fail_here("expected ',' or ')' in #write, found " + describe(plain()));
    }
  }
  advance();
  charge(text.size() / kBytesPerToken);
  // Looked up again: an expression may have called a macro that opened or closed files.
  const auto still = open_files.find(handle);
  if (still == open_files.end()) fail(handle_at, "#write: '" + handle + "' was closed");
  still->second.text += text;
}

void Parser::Impl::directive_read(TokenRef) {
  expect_symbol('(', "after #read");
  const TokenRef handle_at = ref();
  const std::string handle(expect_identifier_raw("in #read"));
  const auto opened = open_files.find(handle);
  // A file #read closed at its end reads nothing more, without an error, as in POV-Ray.
  const bool ended = opened == open_files.end() && ended_files.count(handle) > 0;
  if (!ended && (opened == open_files.end() || opened->second.writing)) {
    fail(handle_at, "#read: '" + handle + "' is not a file opened for reading");
  }
  while (accept_symbol(',')) {
    const TokenRef name_at = ref();
    const std::string name(expect_identifier_raw("in #read"));
    const auto found = open_files.find(handle);
    if (found == open_files.end()) continue;  // the end of the file came: nothing more is read
    OpenFile& file = found->second;
    std::string error;
    bool at_end = false;
    std::optional<Value> value = read_file_value(file, error, at_end);
    if (!error.empty()) fail(name_at, "#read '" + file.path + "': " + error);
    if (value) {
      value->loc = loc(name_at);
      store(scopes.front().serial, name, std::move(*value));
    }
    if (!value || at_end) {
      open_files.erase(handle);
      ended_files.insert(handle);
    }
  }
  expect_symbol(')', "at the end of #read");
}

}  // namespace convray::sdl
