// Scopes as POV-Ray has them: the global table, then one table per include file and per macro
// call, searched innermost first. #declare writes the global table, #local the innermost.
// A macro parameter passed by reference is an Alias in the call's scope: reading it reads the
// caller's variable, and #declare or #local of it writes the caller's variable.
#include <algorithm>

#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {

Value* Parser::Impl::lookup(std::string_view name) {
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    const auto found = scope->values.find(name);
    if (found != scope->values.end()) return &found->second;
    if (scope->aliases.empty()) continue;
    const auto alias = scope->aliases.find(name);
    if (alias != scope->aliases.end()) return resolve(alias->second);
  }
  return nullptr;
}

const Alias* Parser::Impl::innermost_alias(std::string_view name) const {
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    if (scope->values.find(name) != scope->values.end()) return nullptr;
    const auto alias = scope->aliases.find(name);
    if (alias != scope->aliases.end()) return &alias->second;
  }
  return nullptr;
}

std::optional<Alias> Parser::Impl::alias_of(std::string_view name) const {
  if (const Alias* alias = innermost_alias(name)) return *alias;  // a reference passed on
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    if (scope->values.find(name) != scope->values.end()) {
      return Alias{scope->serial, std::string(name), {}};
    }
  }
  return std::nullopt;
}

Value* Parser::Impl::resolve(const Alias& alias) {
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    if (scope->serial != alias.scope) continue;
    const auto found = scope->values.find(alias.name);
    if (found == scope->values.end()) return nullptr;  // #undef'd since
    Value* cursor = &found->second;
    for (const std::size_t flat : alias.element) {
      const auto* array = cursor->get<std::shared_ptr<Array>>();
      if (array == nullptr || *array == nullptr || flat >= (*array)->elements.size()) {
        return nullptr;  // no longer the array it was
      }
      cursor = &(*array)->elements[flat];
    }
    return cursor;
  }
  return nullptr;
}

void Parser::Impl::store_through(const Alias& alias, Value value, TokenRef at) {
  if (alias.element.empty()) return store(alias.scope, alias.name, std::move(value));
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    if (scope->serial != alias.scope) continue;
    const auto found = scope->values.find(alias.name);
    if (found == scope->values.end()) {
      fail(at, quoted(alias.name) + ", whose element was passed to the macro, is undeclared");
    }
    store_element(found->second, alias.element, std::move(value), alias.name, at);
    return;
  }
}

const Value* Parser::Impl::lookup(std::string_view name) const {
  return const_cast<Impl*>(this)->lookup(name);
}

bool Parser::Impl::is_declared(std::string_view name) const {
  return lookup(name) != nullptr || macros.find(name) != macros.end() ||
         functions.find(name) != functions.end() || open_files.find(name) != open_files.end();
}

void Parser::Impl::store(std::uint64_t scope_serial, std::string_view name, Value value) {
  // The scope may be gone: `#local A = 1` as the last tokens of a macro body is finished
  // after the lookahead left the macro, and the value would have died with it anyway.
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    if (scope->serial != scope_serial) continue;
    if (!scope->aliases.empty()) {
      const auto alias = scope->aliases.find(name);
      if (alias != scope->aliases.end()) {
        const Alias target = alias->second;
        return store_through(target, std::move(value), ref());
      }
    }
    const auto found = scope->values.find(name);
    if (found != scope->values.end()) {
      found->second = std::move(value);
    } else {
      scope->values.emplace(std::string(name), std::move(value));
    }
    return;
  }
}

void Parser::Impl::declare_global(std::string_view name, Value value) {
  store(scopes.front().serial, name, std::move(value));
}

void Parser::Impl::declare_local(std::string_view name, Value value) {
  store(scopes.back().serial, name, std::move(value));
}

std::uint64_t Parser::Impl::push_scope() {
  Scope& scope = scopes.emplace_back();
  scope.serial = next_scope_serial++;
  return scope.serial;
}

void Parser::Impl::pop_scope(std::uint64_t serial) {
  if (scopes.size() > 1 && scopes.back().serial == serial) scopes.pop_back();
}

bool Parser::Impl::undeclare(std::string_view name) {
  for (auto scope = scopes.rbegin(); scope != scopes.rend(); ++scope) {
    const auto found = scope->values.find(name);
    if (found != scope->values.end()) {
      scope->values.erase(found);
      return true;
    }
    // #undef of a parameter passed by reference forgets the parameter, not the variable.
    if (const auto alias = scope->aliases.find(name); alias != scope->aliases.end()) {
      scope->aliases.erase(alias);
      return true;
    }
  }
  if (const auto macro = macros.find(name); macro != macros.end()) {
    macros.erase(macro);
    return true;
  }
  if (const auto function = functions.find(name); function != functions.end()) {
    functions.erase(function);
    return true;
  }
  return false;
}

std::string Parser::Impl::did_you_mean(std::string_view name) const {
  // The closest declared name or reserved word, if it is close enough to be a typo: at most
  // a third of the letters wrong (and at least one edit allowed).
  const int allowed = std::max(1, int(name.size()) / 3);
  std::string best;
  int best_distance = allowed + 1;
  const auto consider = [&](std::string_view candidate) {
    if (candidate == name) return;
    const int length_gap = std::abs(int(candidate.size()) - int(name.size()));
    if (length_gap >= best_distance) return;
    const int distance = edit_distance(name, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = std::string(candidate);
    }
  };
  for (const Scope& scope : scopes) {
    for (const auto& entry : scope.values) consider(entry.first);
    for (const auto& entry : scope.aliases) consider(entry.first);
  }
  for (const auto& entry : macros) consider(entry.first);
  for (const auto& entry : functions) consider(entry.first);
  for (std::string_view word : reserved_words()) consider(word);
  if (best.empty()) return {};
  std::string suggestion = " (did you mean ";
  suggestion += quoted(best);
  suggestion += "?)";
  return suggestion;
}

void Parser::Impl::check_deprecated(std::string_view name, TokenRef at) {
  const auto found = deprecations.find(name);
  if (found == deprecations.end()) return;
  Deprecation& deprecation = found->second;
  if (deprecation.once && deprecation.warned) return;
  // Item parsers may peek at the same token more than once: one warning per use.
  if (at.token == last_deprecated_use) return;
  last_deprecated_use = at.token;
  deprecation.warned = true;
  warn(loc(at), quoted(name) + " is deprecated: " + deprecation.message);
}

}  // namespace convray::sdl
