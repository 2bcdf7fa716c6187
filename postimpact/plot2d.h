// Line plots (time histories): axes with "nice" ticks, tick labels, axis labels with units,
// title, legend, several curves; drawn by the small raster code of image.h plus FreeType.
#pragma once

#include <string>
#include <vector>

#include "postimpact/image.h"
#include "postimpact/text_freetype.h"

namespace postimpact {

struct Series {
    std::string name;
    std::vector<double> x, y;
};

struct PlotSpec {
    std::string title, subtitle, xlabel, ylabel;
    std::vector<Series> series;
    int width = 1200, height = 800;
};

// Ticks covering [lo, hi] with about `target` intervals of 1, 2 or 5 x 10^k; lo/hi are widened
// to tick values.  Returns the tick values; *step gets the spacing.
std::vector<double> nice_ticks(double& lo, double& hi, int target, double* step);
// Curve colours (distinct, colour-blind friendly order).
Rgb series_color(int i);

Image draw_plot(const PlotSpec& spec, const Font& font);

}  // namespace postimpact
