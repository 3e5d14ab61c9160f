#include "app/ini_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace convray::app {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxIncludeDepth = 16;
constexpr size_t kMaxFileBytes = size_t(16) << 20;  // INI files are a few lines

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The line without its comment (; or // outside quotes); a quote left open is an error.
std::string strip_comment(const std::string& line, const SourceLoc& where) {
  bool quoted = false;
  size_t quote_column = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') {
      quoted = !quoted;
      quote_column = i;
    } else if (!quoted &&
               (line[i] == ';' || (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '/'))) {
      return line.substr(0, i);
    }
  }
  if (quoted) {
    throw InputError({where.file, where.line, int(quote_column) + 1}, "this quote is never closed");
  }
  return line;
}

struct Reader {
  std::vector<IniEntry> entries;
  std::vector<std::string> open_files;  // for include cycles

  void read(const IniArgument& argument, const SourceLoc& included_from, int depth);
  void read_line(const std::string& text, const SourceLoc& line, const std::string& file,
                 int depth);
  void read_switches(const std::string& text, const SourceLoc& line);
};

std::string read_whole_file(const std::string& path, const SourceLoc& included_from) {
  const SourceLoc at = included_from.file.empty() ? SourceLoc{path} : included_from;
  std::error_code error;
  if (!fs::is_regular_file(path, error)) {
    throw InputError(at, fs::exists(path, error) ? "'" + path + "' is not a regular file"
                                                 : "cannot open INI file '" + path + "'");
  }
  if (fs::file_size(path, error) > kMaxFileBytes) {
    throw InputError(at, "'" + path + "' is too large for an INI file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(at, "cannot open INI file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Whether the line is a "[Name]" section header; sets `name` if so.
bool section_name(const std::string& trimmed, std::string& name) {
  if (trimmed.size() < 2 || trimmed.front() != '[' || trimmed.back() != ']') return false;
  name = trimmed.substr(1, trimmed.size() - 2);
  return true;
}

std::string trim(const std::string& s, size_t& first) {
  first = 0;
  while (first < s.size() && is_space(s[first])) ++first;
  size_t last = s.size();
  while (last > first && is_space(s[last - 1])) --last;
  return s.substr(first, last - first);
}

void Reader::read(const IniArgument& argument, const SourceLoc& included_from, int depth) {
  if (depth > kMaxIncludeDepth) {
    throw InputError(included_from, "INI files include each other more than " +
                                        std::to_string(kMaxIncludeDepth) + " deep");
  }
  std::error_code error;
  const std::string identity = fs::weakly_canonical(argument.path, error).string();
  if (std::find(open_files.begin(), open_files.end(), identity) != open_files.end()) {
    throw InputError(included_from, "'" + argument.path + "' includes itself");
  }
  open_files.push_back(identity);
  const std::string text = read_whole_file(argument.path, included_from);
  if (text.find('\0') != std::string::npos) {
    throw InputError({argument.path}, "not a text file (it holds a NUL byte)");
  }
  const std::string wanted = lower(argument.section);
  bool reading = true, found = wanted.empty();
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const SourceLoc where{argument.path, number, 1};
    size_t indent = 0;
    const std::string content = trim(strip_comment(line, where), indent);
    std::string name;
    if (section_name(content, name)) {
      reading = !wanted.empty() && lower(name) == wanted;
      found = found || reading;
      continue;
    }
    if (reading && !content.empty()) {
      read_line(content, {argument.path, number, int(indent) + 1}, argument.path, depth);
    }
  }
  if (!found) {
    throw InputError(included_from.file.empty() ? SourceLoc{argument.path} : included_from,
                     "'" + argument.path + "' has no section [" + argument.section + "]");
  }
  open_files.pop_back();
}

void Reader::read_line(const std::string& text, const SourceLoc& line, const std::string& file,
                       int depth) {
  if (text[0] == '+' || text[0] == '-') {
    read_switches(text, line);
    return;
  }
  const size_t eq = text.find('=');
  if (eq == std::string::npos) {
    throw InputError(line, "expected Key=value, a [section] or +switches, got '" + text + "'");
  }
  size_t unused = 0;
  IniEntry entry;
  entry.loc = line;
  entry.key = trim(text.substr(0, eq), unused);
  size_t value_offset = 0;
  std::string value = trim(text.substr(eq + 1), value_offset);
  entry.value_loc = {line.file, line.line, line.column + int(eq + 1 + value_offset)};
  if (entry.key.empty()) throw InputError(line, "a value without a key: '" + text + "'");
  if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
    value = value.substr(1, value.size() - 2);
  }
  entry.value = value;
  if (lower(entry.key) == "include_ini") {
    if (value.empty()) throw InputError(entry.value_loc, "Include_INI: expected a file name");
    IniArgument included = split_ini_argument(value);
    // Relative names: the current folder first (as POV-Ray), then the including file's folder.
    std::error_code error;
    if (!fs::exists(included.path, error)) {
      const fs::path beside = fs::path(file).parent_path() / included.path;
      if (fs::exists(beside, error)) included.path = beside.string();
    }
    read(included, entry.value_loc, depth + 1);
    return;
  }
  entries.push_back(entry);
}

// "+W640 +H480 -D": each switch an entry of its own.
void Reader::read_switches(const std::string& text, const SourceLoc& line) {
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    if (i >= text.size()) break;
    size_t end = i;
    bool quoted = false;
    while (end < text.size() && (quoted || !is_space(text[end]))) {
      if (text[end] == '"') quoted = !quoted;
      ++end;
    }
    std::string word = text.substr(i, end - i);
    const SourceLoc where{line.file, line.line, line.column + int(i)};
    if (word[0] != '+' && word[0] != '-') {
      throw InputError(where, "expected a +switch or -switch here, got '" + word + "'");
    }
    word.erase(std::remove(word.begin(), word.end(), '"'), word.end());
    entries.push_back({where, where, "", word});
    i = end;
  }
}

}  // namespace

bool is_ini_argument(const std::string& argument) {
  const IniArgument split = split_ini_argument(argument);
  const std::string name = lower(split.path);
  return name.size() > 4 && name.ends_with(".ini");
}

IniArgument split_ini_argument(const std::string& argument) {
  if (!argument.empty() && argument.back() == ']') {
    const size_t open = argument.rfind('[');
    if (open != std::string::npos && open > 0) {
      return {argument.substr(0, open), argument.substr(open + 1, argument.size() - open - 2)};
    }
  }
  return {argument, ""};
}

std::vector<IniEntry> read_ini(const IniArgument& argument) {
  Reader reader;
  reader.read(argument, SourceLoc{}, 0);
  return std::move(reader.entries);
}

}  // namespace convray::app
