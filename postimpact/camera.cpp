#include "postimpact/camera.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace postimpact {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kIsoEl = 35.264389682754654;  // atan(1/sqrt(2)) in degrees

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalized(Vec3 a) {
    const double n = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    if (n > 0) for (double& x : a) x /= n;
    return a;
}
}  // namespace

bool named_view(const std::string& n, View& v) {
    const int up = v.up;
    auto set = [&](double az, double el) { v = View{az, el, up}; return true; };
    if (n == "iso" || n == "isometric") return set(45.0, kIsoEl);
    if (n == "right" || n == "+x") return set(0.0, 0.0);
    if (n == "left" || n == "-x") return set(180.0, 0.0);
    if (n == "back" || n == "+y") return set(90.0, 0.0);
    if (n == "front" || n == "-y") return set(-90.0, 0.0);
    if (n == "top" || n == "+z") return set(-90.0, 90.0);
    if (n == "bottom" || n == "-z") return set(-90.0, -90.0);
    return false;
}

std::string view_name(const View& v) {
    if (std::fabs(v.azimuth - 45.0) < 1e-9 && std::fabs(v.elevation - kIsoEl) < 1e-6) return "iso";
    char buf[64];
    std::snprintf(buf, sizeof buf, "az %g el %g", v.azimuth, v.elevation);
    return buf;
}

Camera make_camera(const View& v) {
    // axes of the up frame: A, B horizontal, U up (cyclic)
    const int u = ((v.up % 3) + 3) % 3, a = (u + 1) % 3, b = (u + 2) % 3;
    const double az = v.azimuth * kPi / 180.0, el = v.elevation * kPi / 180.0;
    Vec3 eye{0, 0, 0}, U{0, 0, 0};
    eye[a] = std::cos(el) * std::cos(az);
    eye[b] = std::cos(el) * std::sin(az);
    eye[u] = std::sin(el);
    U[u] = 1.0;
    const Vec3 f{-eye[0], -eye[1], -eye[2]};
    Vec3 right = cross(f, U);
    if (std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]) < 1e-9) {
        right = {0, 0, 0};
        right[a] = -std::sin(az);
        right[b] = std::cos(az);
    }
    Camera c;
    c.right = normalized(right);
    c.eye = normalized(eye);
    c.up = normalized(cross(c.right, f));
    // remove round-off noise so that axis views are exact
    for (Vec3* w : {&c.right, &c.up, &c.eye})
        for (double& x : *w)
            if (std::fabs(x) < 1e-15) x = 0.0;
    return c;
}

void Bounds::add(const Camera& c, const double* p) {
    const double x = c.sx(p), y = c.sy(p), d = c.depth(p);
    xmin = std::min(xmin, x); xmax = std::max(xmax, x);
    ymin = std::min(ymin, y); ymax = std::max(ymax, y);
    dmin = std::min(dmin, d); dmax = std::max(dmax, d);
}

Window fit_window(const Bounds& b, int w, int h, double margin) {
    Window win;
    if (b.empty()) return win;
    win.cx = 0.5 * (b.xmin + b.xmax);
    win.cy = 0.5 * (b.ymin + b.ymax);
    double hw = 0.5 * (b.xmax - b.xmin), hh = 0.5 * (b.ymax - b.ymin);
    const double size = std::max({hw, hh, 1e-30});
    hw = std::max(hw, 1e-6 * size);
    hh = std::max(hh, 1e-6 * size);
    const double aspect = static_cast<double>(w) / std::max(h, 1);
    hw *= 1.0 + 2.0 * margin;
    hh *= 1.0 + 2.0 * margin;
    if (hw / hh > aspect) hh = hw / aspect;
    else hw = hh * aspect;
    win.half_w = hw;
    win.half_h = hh;
    const double dpad = 0.05 * std::max(b.dmax - b.dmin, size) + 1e-30;
    win.dmin = b.dmin - dpad;
    win.dmax = b.dmax + dpad;
    return win;
}

}  // namespace postimpact
