#pragma once
// Text files as UTF-8: a UTF-8 byte-order mark is dropped, UTF-16 (either byte order, told by
// its byte-order mark, as Windows tools write "Unicode" text) is converted. Internal to
// src/mesh.
#include <string>
#include <string_view>

namespace convray::mesh {

// The text of `bytes` as UTF-8: a view into `bytes` itself, or into `storage` when it had
// to be converted. Throws InputError for UTF-16 that is cut in half or has an unpaired
// surrogate.
std::string_view as_utf8(std::string_view bytes, std::string& storage, const std::string& file);

}  // namespace convray::mesh
