// PNG writing (libpng, RGB 8 bit, fixed compression settings, no time or text chunks: the same
// image always gives the same bytes) and reading (for tests and tools).
#pragma once

#include <string>
#include <vector>

#include "postimpact/image.h"

namespace postimpact {

// Writes img (alpha dropped) to path.  Throws std::runtime_error on failure.
void write_png(const std::string& path, const Image& img);
// Encodes img into PNG bytes in memory.
std::vector<unsigned char> encode_png(const Image& img);
// Reads any PNG into RGBA8.  Throws std::runtime_error on failure.
Image read_png(const std::string& path);

}  // namespace postimpact
