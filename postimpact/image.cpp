#include "postimpact/image.h"

#include <algorithm>
#include <cmath>

namespace postimpact {

Image::Image(int w, int h, Rgb bg) : width(w), height(h), rgba(4 * static_cast<std::size_t>(w) * h) {
    for (std::size_t i = 0; i < rgba.size(); i += 4) {
        rgba[i] = bg.r; rgba[i + 1] = bg.g; rgba[i + 2] = bg.b; rgba[i + 3] = 255;
    }
}

void Image::blend(int x, int y, Rgb c, double a) {
    if (!inside(x, y) || a <= 0.0) return;
    if (a > 1.0) a = 1.0;
    std::uint8_t* p = px(x, y);
    auto mix = [a](std::uint8_t d, std::uint8_t s) {
        return static_cast<std::uint8_t>(std::lround(d + (static_cast<double>(s) - d) * a));
    };
    p[0] = mix(p[0], c.r); p[1] = mix(p[1], c.g); p[2] = mix(p[2], c.b); p[3] = 255;
}

void Image::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
    x0 = std::max(x0, 0); y0 = std::max(y0, 0);
    x1 = std::min(x1, width); y1 = std::min(y1, height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            std::uint8_t* p = px(x, y);
            p[0] = c.r; p[1] = c.g; p[2] = c.b; p[3] = 255;
        }
}

void Image::rect_outline(int x0, int y0, int x1, int y1, Rgb c, int t) {
    fill_rect(x0, y0, x1, y0 + t, c);
    fill_rect(x0, y1 - t, x1, y1, c);
    fill_rect(x0, y0, x0 + t, y1, c);
    fill_rect(x1 - t, y0, x1, y1, c);
}

void Image::line(double x0, double y0, double x1, double y1, Rgb c, double w) {
    // Coverage from the distance of the pixel centre to the segment (capsule of radius w/2).
    const double r = 0.5 * w;
    const int xa = static_cast<int>(std::floor(std::min(x0, x1) - r - 1));
    const int xb = static_cast<int>(std::ceil(std::max(x0, x1) + r + 1));
    const int ya = static_cast<int>(std::floor(std::min(y0, y1) - r - 1));
    const int yb = static_cast<int>(std::ceil(std::max(y0, y1) + r + 1));
    const double dx = x1 - x0, dy = y1 - y0, len2 = dx * dx + dy * dy;
    for (int y = std::max(ya, 0); y <= std::min(yb, height - 1); ++y)
        for (int x = std::max(xa, 0); x <= std::min(xb, width - 1); ++x) {
            double t = len2 > 0 ? ((x - x0) * dx + (y - y0) * dy) / len2 : 0.0;
            t = std::clamp(t, 0.0, 1.0);
            const double ex = x0 + t * dx - x, ey = y0 + t * dy - y;
            const double d = std::sqrt(ex * ex + ey * ey);
            const double cov = std::clamp(r + 0.5 - d, 0.0, 1.0);
            if (cov > 0) blend(x, y, c, cov);
        }
}

void Image::polyline(const std::vector<double>& xy, Rgb c, double w) {
    // Draw into a coverage mask first so that joints are not blended twice.
    if (xy.size() < 4) return;
    double xmin = xy[0], xmax = xy[0], ymin = xy[1], ymax = xy[1];
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
        xmin = std::min(xmin, xy[i]); xmax = std::max(xmax, xy[i]);
        ymin = std::min(ymin, xy[i + 1]); ymax = std::max(ymax, xy[i + 1]);
    }
    const double r = 0.5 * w;
    const int X0 = std::max(0, static_cast<int>(std::floor(xmin - r - 1)));
    const int X1 = std::min(width - 1, static_cast<int>(std::ceil(xmax + r + 1)));
    const int Y0 = std::max(0, static_cast<int>(std::floor(ymin - r - 1)));
    const int Y1 = std::min(height - 1, static_cast<int>(std::ceil(ymax + r + 1)));
    if (X1 < X0 || Y1 < Y0) return;
    const int mw = X1 - X0 + 1;
    std::vector<float> mask(static_cast<std::size_t>(mw) * (Y1 - Y0 + 1), 0.0f);
    for (std::size_t i = 0; i + 3 < xy.size(); i += 2) {
        const double ax = xy[i], ay = xy[i + 1], bx = xy[i + 2], by = xy[i + 3];
        const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
        const int xa = std::max(X0, static_cast<int>(std::floor(std::min(ax, bx) - r - 1)));
        const int xb = std::min(X1, static_cast<int>(std::ceil(std::max(ax, bx) + r + 1)));
        const int ya = std::max(Y0, static_cast<int>(std::floor(std::min(ay, by) - r - 1)));
        const int yb = std::min(Y1, static_cast<int>(std::ceil(std::max(ay, by) + r + 1)));
        for (int y = ya; y <= yb; ++y)
            for (int x = xa; x <= xb; ++x) {
                double t = len2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / len2 : 0.0;
                t = std::clamp(t, 0.0, 1.0);
                const double ex = ax + t * dx - x, ey = ay + t * dy - y;
                const float cov = static_cast<float>(std::clamp(r + 0.5 - std::sqrt(ex * ex + ey * ey), 0.0, 1.0));
                float& m = mask[static_cast<std::size_t>(y - Y0) * mw + (x - X0)];
                m = std::max(m, cov);
            }
    }
    for (int y = Y0; y <= Y1; ++y)
        for (int x = X0; x <= X1; ++x) {
            const float m = mask[static_cast<std::size_t>(y - Y0) * mw + (x - X0)];
            if (m > 0) blend(x, y, c, m);
        }
}

void Image::blit(const Image& src, int x, int y) {
    for (int j = 0; j < src.height; ++j)
        for (int i = 0; i < src.width; ++i) {
            if (!inside(x + i, y + j)) continue;
            const std::uint8_t* s = src.px(i, j);
            std::uint8_t* d = px(x + i, y + j);
            d[0] = s[0]; d[1] = s[1]; d[2] = s[2]; d[3] = s[3];
        }
}

Image Image::downsample(int f) const {
    if (f <= 1) return *this;
    Image out(width / f, height / f);
    const int n = f * f;
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            int s[4] = {0, 0, 0, 0};
            for (int j = 0; j < f; ++j)
                for (int i = 0; i < f; ++i) {
                    const std::uint8_t* p = px(x * f + i, y * f + j);
                    for (int k = 0; k < 4; ++k) s[k] += p[k];
                }
            std::uint8_t* d = out.px(x, y);
            for (int k = 0; k < 4; ++k) d[k] = static_cast<std::uint8_t>((s[k] + n / 2) / n);
        }
    return out;
}

double non_background_fraction(const Image& img, Rgb bg) {
    if (img.width == 0 || img.height == 0) return 0.0;
    std::size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (!(img.get(x, y) == bg)) ++n;
    return static_cast<double>(n) / (static_cast<double>(img.width) * img.height);
}

}  // namespace postimpact
