// Text through FreeType (anti-aliased, UTF-8), rasterised into an Image after the GL pass.
#pragma once

#include <memory>
#include <string>

#include "postimpact/image.h"

namespace postimpact {

enum class HAlign { Left, Center, Right };

class Font {
public:
    // Loads a TrueType font; path empty: the default (DejaVu Sans, fonts-dejavu-core).  Throws
    // std::runtime_error when the font cannot be loaded.
    explicit Font(const std::string& path = "");
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    // Width in pixels of text at pixel size px.
    int measure(const std::string& text, int px) const;
    int ascent(int px) const;   // above the baseline
    int descent(int px) const;  // below the baseline (positive)
    // Draws text with its baseline at y; x is the left end, the centre or the right end.
    // rotated: 90 degrees counter-clockwise (reads bottom to top), x/y then refer to the rotated
    // frame: the baseline is the vertical line at x, and the alignment is along y.
    void draw(Image& img, int x, int y, const std::string& text, int px, Rgb color,
              HAlign align = HAlign::Left, bool rotated = false) const;
    const std::string& path() const { return path_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string path_;
};

// Default font path (compile-time, overridable with environment POSTIMPACT_FONT).
std::string default_font_path();

}  // namespace postimpact
