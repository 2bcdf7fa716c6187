// Orthographic axonometric views: azimuth/elevation about an "up" axis, named views along the
// axes, and fitting a set of points into a viewport.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace postimpact {

using Vec3 = std::array<double, 3>;

struct View {
    double azimuth = 45.0;      // degrees, about the up axis, from the first horizontal axis
    double elevation = 35.264;  // degrees above the horizontal plane (isometric: atan(1/sqrt 2))
    int up = 2;                 // 0 x, 1 y, 2 z (the bar axis of the Taylor deck)
};

// iso (default), isometric, front (-y), back (+y), right (+x), left (-x), top (+z), bottom (-z)
// and +x -x +y -y +z -z (the side the viewer is on; "up" frame: the names refer to the axes
// that follow the up axis cyclically, e.g. up z: x y, up y: z x).  False if unknown.
bool named_view(const std::string& name, View& v);
// "iso" for the default angles, else "az A el E".
std::string view_name(const View& v);

struct Camera {
    Vec3 right{1, 0, 0};  // screen x
    Vec3 up{0, 1, 0};     // screen y
    Vec3 eye{0, 0, 1};    // toward the viewer
    double sx(const double* p) const { return right[0] * p[0] + right[1] * p[1] + right[2] * p[2]; }
    double sy(const double* p) const { return up[0] * p[0] + up[1] * p[1] + up[2] * p[2]; }
    double depth(const double* p) const { return eye[0] * p[0] + eye[1] * p[1] + eye[2] * p[2]; }
};
Camera make_camera(const View& v);

// Window of the orthographic projection (model units, screen axes).
struct Window {
    double cx = 0, cy = 0, half_w = 1, half_h = 1;  // centre and half extents
    double dmin = -1, dmax = 1;                     // depth range (toward the viewer)
};
// Projected bounding box of points (3 per point); grows *w (if it has been set, valid = true).
struct Bounds {
    double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300, dmin = 1e300, dmax = -1e300;
    void add(const Camera& c, const double* p);
    bool empty() const { return xmin > xmax; }
};
// Window that shows b in a viewport of aspect w:h with a relative margin on each side.
Window fit_window(const Bounds& b, int w, int h, double margin = 0.06);

}  // namespace postimpact
