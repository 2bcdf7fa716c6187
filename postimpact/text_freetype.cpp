#include "postimpact/text_freetype.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <cstdlib>
#include <stdexcept>
#include <vector>

#ifndef POSTIMPACT_DEFAULT_FONT
#define POSTIMPACT_DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

namespace postimpact {

namespace {

std::vector<char32_t> utf8_decode(const std::string& s) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        char32_t cp = 0;
        int n = 0;
        if (c < 0x80) { cp = c; n = 0; }
        else if ((c & 0xE0) == 0xC0) { cp = c & 0x1F; n = 1; }
        else if ((c & 0xF0) == 0xE0) { cp = c & 0x0F; n = 2; }
        else if ((c & 0xF8) == 0xF0) { cp = c & 0x07; n = 3; }
        else { out.push_back(U'?'); ++i; continue; }
        bool ok = true;
        for (int k = 1; k <= n; ++k) {
            if (i + k >= s.size() || (static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) { ok = false; break; }
            cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
        }
        if (!ok) { out.push_back(U'?'); ++i; continue; }
        out.push_back(cp);
        i += n + 1;
    }
    return out;
}

}  // namespace

std::string default_font_path() {
    if (const char* e = std::getenv("POSTIMPACT_FONT"); e && *e) return e;
    return POSTIMPACT_DEFAULT_FONT;
}

struct Font::Impl {
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
    mutable int size = 0;
    void set_size(int px) const {
        if (px != size) {
            FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(px));
            size = px;
        }
    }
};

Font::Font(const std::string& path) : impl_(std::make_unique<Impl>()), path_(path.empty() ? default_font_path() : path) {
    if (FT_Init_FreeType(&impl_->lib)) throw std::runtime_error("FreeType: initialisation failed");
    if (FT_New_Face(impl_->lib, path_.c_str(), 0, &impl_->face)) {
        FT_Done_FreeType(impl_->lib);
        impl_->lib = nullptr;
        throw std::runtime_error("FreeType: cannot load font " + path_ +
                                 " (Debian package fonts-dejavu-core, or --font PATH)");
    }
}

Font::~Font() {
    if (impl_) {
        if (impl_->face) FT_Done_Face(impl_->face);
        if (impl_->lib) FT_Done_FreeType(impl_->lib);
    }
}

int Font::measure(const std::string& text, int px) const {
    impl_->set_size(px);
    long w = 0;
    FT_UInt prev = 0;
    const bool kern = FT_HAS_KERNING(impl_->face);
    for (char32_t c : utf8_decode(text)) {
        const FT_UInt gi = FT_Get_Char_Index(impl_->face, c);
        if (kern && prev && gi) {
            FT_Vector d;
            FT_Get_Kerning(impl_->face, prev, gi, FT_KERNING_DEFAULT, &d);
            w += d.x;
        }
        if (FT_Load_Glyph(impl_->face, gi, FT_LOAD_DEFAULT)) continue;
        w += impl_->face->glyph->advance.x;
        prev = gi;
    }
    return static_cast<int>((w + 32) >> 6);
}

int Font::ascent(int px) const {
    impl_->set_size(px);
    return static_cast<int>((impl_->face->size->metrics.ascender + 32) >> 6);
}

int Font::descent(int px) const {
    impl_->set_size(px);
    return static_cast<int>((-impl_->face->size->metrics.descender + 32) >> 6);
}

void Font::draw(Image& img, int x, int y, const std::string& text, int px, Rgb color, HAlign align,
                bool rotated) const {
    const int w = measure(text, px);
    int pen = 0;  // along the baseline, pixels from the start
    if (align == HAlign::Center) pen = -w / 2;
    if (align == HAlign::Right) pen = -w;
    impl_->set_size(px);
    FT_Face f = impl_->face;
    const bool kern = FT_HAS_KERNING(f);
    long pen26 = static_cast<long>(pen) * 64;
    FT_UInt prev = 0;
    for (char32_t c : utf8_decode(text)) {
        const FT_UInt gi = FT_Get_Char_Index(f, c);
        if (kern && prev && gi) {
            FT_Vector d;
            FT_Get_Kerning(f, prev, gi, FT_KERNING_DEFAULT, &d);
            pen26 += d.x;
        }
        if (FT_Load_Glyph(f, gi, FT_LOAD_RENDER)) continue;
        const FT_GlyphSlot g = f->glyph;
        const FT_Bitmap& bm = g->bitmap;
        const int ox = static_cast<int>((pen26 + 32) >> 6) + g->bitmap_left;  // along the baseline
        const int oy = -g->bitmap_top;                                      // across (down positive)
        for (unsigned r = 0; r < bm.rows; ++r)
            for (unsigned q = 0; q < bm.width; ++q) {
                const unsigned char a = bm.buffer[r * bm.pitch + q];
                if (!a) continue;
                const int u = ox + static_cast<int>(q), v = oy + static_cast<int>(r);
                if (!rotated) img.blend(x + u, y + v, color, a / 255.0);
                else img.blend(x + v, y - u, color, a / 255.0);
            }
        pen26 += g->advance.x;
        prev = gi;
    }
}

}  // namespace postimpact
