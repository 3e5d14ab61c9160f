#pragma once
// A PNG's image data (the content of its IDAT chunk) made on every core: the rows filtered
// with Paeth's predictor, cut into bands of whole rows, each band deflated on its own, and the
// pieces joined into one zlib stream, as pigz joins its blocks: every band but the last ends
// on a byte boundary with an empty stored block (zlib's Z_SYNC_FLUSH), the last one closes the
// stream, and the Adler-32 of the whole is combined from the bands' own (adler32_combine).
// Each band takes the filtered bytes just before it (zlib's 32 KiB window) as its dictionary,
// so the bands compress about as one stream would (the dragon's 800x600 picture: 234,522
// bytes, libpng 234,819), in half the time on two cores.
//
// Any PNG decoder reads the result: the stream is one valid zlib stream whatever the bands
// (tests/core/png_deflate_test.cpp inflates it with zlib and checks every byte against the
// filter applied row by row).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace convray {

// The zlib stream of the filtered scanlines of an image of `height` rows of `row_bytes`
// bytes each (`pixels`, rows top first), each pixel `pixel_bytes` bytes: every row filter
// type 4 (Paeth) then its filtered bytes. `level`: zlib's compression level. `bands`: how
// many pieces to deflate in parallel (at least 1; fewer when there are fewer rows).
std::vector<unsigned char> png_image_data(const unsigned char* pixels, size_t row_bytes,
                                          size_t height, size_t pixel_bytes, int level,
                                          size_t bands);

// One row's Paeth filter: `out` (row_bytes + 1 bytes) gets the filter type 4 then each byte
// less the predictor of its left, upper and upper-left neighbours (`above` null for the first
// row: zeros). The PNG specification's definition, byte by byte.
void paeth_filter_row(const unsigned char* row, const unsigned char* above, size_t row_bytes,
                      size_t pixel_bytes, unsigned char* out);

}  // namespace convray
