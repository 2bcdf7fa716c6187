// RGBA8 image (top row first) and the small 2-D raster primitives POST-IMPACT draws with after
// the OpenGL pass: filled rectangles, anti-aliased thick lines, pixel blending.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace postimpact {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb&) const = default;
};

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // 4*width*height, row 0 = top

    Image() = default;
    Image(int w, int h, Rgb background = {255, 255, 255});

    std::uint8_t* px(int x, int y) { return &rgba[4 * (static_cast<std::size_t>(y) * width + x)]; }
    const std::uint8_t* px(int x, int y) const {
        return &rgba[4 * (static_cast<std::size_t>(y) * width + x)];
    }
    Rgb get(int x, int y) const { const auto* p = px(x, y); return {p[0], p[1], p[2]}; }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }

    // Blends colour c over pixel (x, y) with coverage a in [0, 1] (ignored outside the image).
    void blend(int x, int y, Rgb c, double a);
    void fill_rect(int x0, int y0, int x1, int y1, Rgb c);   // [x0, x1) x [y0, y1)
    void rect_outline(int x0, int y0, int x1, int y1, Rgb c, int thickness = 1);
    // Anti-aliased line of the given width (pixels) between pixel-centre coordinates.
    void line(double x0, double y0, double x1, double y1, Rgb c, double width = 1.0);
    void polyline(const std::vector<double>& xy, Rgb c, double width = 1.0);
    // Copies src into this image with its top-left corner at (x, y).
    void blit(const Image& src, int x, int y);
    // Box-filter downsampling by an integer factor.
    Image downsample(int factor) const;
};

// Fraction of pixels that differ from the colour bg.
double non_background_fraction(const Image& img, Rgb bg = {255, 255, 255});

}  // namespace postimpact
