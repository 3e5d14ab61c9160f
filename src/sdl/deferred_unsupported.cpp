// Declarations that need what convray cannot render yet. POV-Ray's include files declare far
// more than a scene uses (stones2.inc's crackle textures, skies.inc's sky spheres), so such a
// declaration must not stop a scene that never uses it; a scene that does use it fails where
// it does, quoting the feature and where the declaration needed it. Never a silently wrong
// picture, and no refusal for what a scene does not draw.
#include "sdl/diagnostics.hpp"
#include "sdl/parser_impl.hpp"

namespace convray::sdl {

void Parser::fail_unsupported(const SourceLoc& loc, const std::string& message) const {
  impl_->fail_unsupported(loc, message);
}

void Parser::fail_unsupported_here(const std::string& message) {
  impl_->settle();
  impl_->fail_unsupported(impl_->loc(impl_->ref()), message);
}

void Parser::block_opened() { ++impl_->open_blocks; }
void Parser::block_closed() { --impl_->open_blocks; }

std::optional<UnsupportedItem> Parser::parse_or_skip_unsupported(
    const std::function<void()>& parse) {
  const int depth = impl_->open_blocks;
  try {
    parse();
    return std::nullopt;
  } catch (const UnsupportedError& error) {
    // Outside braces of its own (an expression), there is no end to read up to.
    if (impl_->open_blocks <= depth) throw;
    UnsupportedItem item{error.feature(), error.loc()};
    while (impl_->open_blocks > depth) {
      const Token token = next();
      if (token.kind == Token::Kind::end) {
        fail(token.loc, "missing '}' to close the item that needs what is not supported: " +
                            item.feature + " (at " + item.feature_at.str() + ")");
      }
      if (token.kind != Token::Kind::symbol) continue;
      if (token.text == "{") ++impl_->open_blocks;
      if (token.text == "}") --impl_->open_blocks;
    }
    return item;
  }
}

void Parser::Impl::fail_unsupported(const SourceLoc& at, const std::string& message,
                                    const std::string& feature) const {
  const auto file = files_by_name.find(at.file);
  const std::string text = file == files_by_name.end()
                               ? message
                               : with_source_line(message, file->second->text, at.line, at.column);
  throw UnsupportedError(at, text, feature.empty() ? message : feature);
}

void Parser::Impl::check_usable(const Value& value, std::string_view name, TokenRef at) const {
  const auto* unsupported = value.get<std::shared_ptr<const UnsupportedItem>>();
  if (unsupported == nullptr) return;
  const UnsupportedItem& item = **unsupported;
  // An UnsupportedError again, of the same feature: a declaration that uses this one
  // stands as well.
  fail_unsupported(loc(at),
                   item.feature + " (at " + item.feature_at.str() + "): " + quoted(name) +
                       ", declared at " + value.loc.str() + ", needs it",
                   item.feature);
}

}  // namespace convray::sdl
