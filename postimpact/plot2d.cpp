#include "postimpact/plot2d.h"

#include <algorithm>
#include <cmath>

#include "postimpact/quantities.h"

namespace postimpact {

std::vector<double> nice_ticks(double& lo, double& hi, int target, double* step_out) {
    if (!(hi > lo)) {
        const double d = std::max(std::fabs(lo) * 0.1, 1e-12);
        lo -= d;
        hi += d;
    }
    const double raw = (hi - lo) / std::max(target, 1);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw * 0.999) { step = m * mag; break; }
    lo = std::floor(lo / step + 1e-9) * step;
    hi = std::ceil(hi / step - 1e-9) * step;
    std::vector<double> t;
    const int n = static_cast<int>(std::lround((hi - lo) / step));
    for (int i = 0; i <= n; ++i) {
        double v = lo + i * step;
        if (std::fabs(v) < 1e-9 * step) v = 0.0;
        t.push_back(v);
    }
    if (step_out) *step_out = step;
    return t;
}

Rgb series_color(int i) {
    static const Rgb pal[] = {{0, 90, 181},  {220, 50, 32},  {0, 150, 70},  {230, 140, 0},
                              {120, 60, 170}, {0, 170, 190}, {200, 60, 150}, {110, 110, 110},
                              {150, 110, 40}, {90, 160, 230}};
    return pal[i % 10];
}

Image draw_plot(const PlotSpec& sp, const Font& font) {
    const int W = sp.width, H = sp.height;
    Image img(W, H);
    const int unit = std::max(8, std::min(W, H * 5 / 2) / 50);  // 24 px at 1200x800
    const int title_px = unit * 6 / 5, label_px = unit * 9 / 10, tick_px = unit * 3 / 4;
    const Rgb text{20, 20, 20}, grid{225, 225, 225}, axis{0, 0, 0};

    double xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
    for (const auto& s : sp.series)
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            xlo = std::min(xlo, s.x[i]); xhi = std::max(xhi, s.x[i]);
            ylo = std::min(ylo, s.y[i]); yhi = std::max(yhi, s.y[i]);
        }
    if (xlo > xhi) { xlo = 0; xhi = 1; ylo = 0; yhi = 1; }
    double xstep = 1, ystep = 1;
    const std::vector<double> xt = nice_ticks(xlo, xhi, 8, &xstep);
    const std::vector<double> yt = nice_ticks(ylo, yhi, 6, &ystep);

    // plot frame: room for the y tick labels and the rotated y label on the left
    int ytick_w = 0;
    for (double v : yt) ytick_w = std::max(ytick_w, font.measure(format_tick(v, ystep), tick_px));
    const int left = unit + label_px + unit / 2 + ytick_w + unit / 2;
    // legend rows (flow layout between the title and the frame)
    const int line_len = unit * 2, row_h = tick_px * 3 / 2, gap = unit;
    struct Item { int x, row; };
    std::vector<Item> items;
    int rows = 0;
    {
        const int avail = W - 4 * unit;
        int x = 0;
        for (const auto& s : sp.series) {
            const int iw = line_len + unit / 2 + font.measure(s.name, tick_px);
            if (x > 0 && x + iw > avail) { x = 0; ++rows; }
            items.push_back({x, rows});
            x += iw + gap;
        }
        if (!sp.series.empty()) ++rows;
    }
    const int legend_top = (sp.title.empty() ? 0 : unit + title_px) + (sp.subtitle.empty() ? 0 : label_px + unit / 3) + unit / 2;
    const int top = legend_top + rows * row_h + unit / 2 + unit / 2;
    const int right = W - unit * 3 / 2;
    const int bottom = H - (unit + label_px + unit / 2 + tick_px + unit / 2);
    auto X = [&](double v) { return left + (v - xlo) / (xhi - xlo) * (right - left); };
    auto Y = [&](double v) { return bottom - (v - ylo) / (yhi - ylo) * (bottom - top); };

    // title
    font.draw(img, W / 2, unit + font.ascent(title_px), sp.title, title_px, text, HAlign::Center);
    if (!sp.subtitle.empty())
        font.draw(img, W / 2, unit + title_px + unit / 3 + font.ascent(label_px), sp.subtitle, label_px, {70, 70, 70}, HAlign::Center);
    // grid and ticks
    for (double v : xt) {
        const int x = static_cast<int>(std::lround(X(v)));
        img.fill_rect(x, top, x + 1, bottom, grid);
        img.fill_rect(x, bottom, x + 1, bottom + unit / 3, axis);
        font.draw(img, x, bottom + unit / 3 + unit / 4 + font.ascent(tick_px), format_tick(v, xstep), tick_px, text, HAlign::Center);
    }
    for (double v : yt) {
        const int y = static_cast<int>(std::lround(Y(v)));
        img.fill_rect(left, y, right, y + 1, grid);
        img.fill_rect(left - unit / 3, y, left, y + 1, axis);
        font.draw(img, left - unit / 3 - unit / 4, y + font.ascent(tick_px) * 2 / 5, format_tick(v, ystep), tick_px, text, HAlign::Right);
    }
    if (ylo < 0 && yhi > 0) {
        const int y0 = static_cast<int>(std::lround(Y(0.0)));
        img.fill_rect(left, y0, right, y0 + 1, {150, 150, 150});
    }
    img.rect_outline(left, top, right + 1, bottom + 1, axis);
    // axis labels
    font.draw(img, (left + right) / 2, H - unit, sp.xlabel, label_px, text, HAlign::Center);
    font.draw(img, unit + font.ascent(label_px), (top + bottom) / 2, sp.ylabel, label_px, text, HAlign::Center, true);

    // curves
    for (std::size_t k = 0; k < sp.series.size(); ++k) {
        const Series& s = sp.series[k];
        std::vector<double> xy;
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            xy.push_back(X(s.x[i]));
            xy.push_back(Y(s.y[i]));
        }
        const Rgb c = series_color(static_cast<int>(k));
        img.polyline(xy, c, std::max(2.0, unit / 10.0));
        if (xy.size() <= 2 * 60)  // mark the plot states when there are few
            for (std::size_t i = 0; i + 1 < xy.size(); i += 2)
                img.fill_rect(static_cast<int>(xy[i]) - 2, static_cast<int>(xy[i + 1]) - 2,
                              static_cast<int>(xy[i]) + 3, static_cast<int>(xy[i + 1]) + 3, c);
    }
    // legend: rows centred above the frame
    for (int r = 0; r < rows; ++r) {
        int row_w = 0;
        for (std::size_t k = 0; k < items.size(); ++k)
            if (items[k].row == r)
                row_w = items[k].x + line_len + unit / 2 + font.measure(sp.series[k].name, tick_px);
        const int x0 = (W - row_w) / 2;
        for (std::size_t k = 0; k < items.size(); ++k) {
            if (items[k].row != r) continue;
            const int x = x0 + items[k].x, y = legend_top + r * row_h + row_h / 2;
            const Rgb c = series_color(static_cast<int>(k));
            img.line(x, y, x + line_len, y, c, std::max(2.0, unit / 10.0));
            font.draw(img, x + line_len + unit / 2, y + font.ascent(tick_px) * 2 / 5, sp.series[k].name, tick_px, text);
        }
    }
    return img;
}

}  // namespace postimpact
