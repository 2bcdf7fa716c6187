// Offscreen OpenGL rendering through OSMesa (Mesa's software rasteriser): shaded exterior
// faces with fringe bands (a 1-D texture of the colour bands, nearest filtering, on the
// interpolated fringe coordinate), element edges on top (polygon offset), supersampled.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "postimpact/camera.h"
#include "postimpact/image.h"
#include "postimpact/mesh_surface.h"

namespace postimpact {

struct RenderMesh {
    const std::vector<double>* coords = nullptr;        // 3*numnp current coordinates
    const std::vector<SurfaceFace>* faces = nullptr;
    std::vector<std::array<double, 3>> copies{{1, 1, 1}};  // reflection signs (mirror_copies)
    const std::vector<double>* node_t = nullptr;  // fringe coordinate per node (smooth), or
    const std::vector<double>* elem_t = nullptr;  // per element (flat); neither: plain surface
    const std::vector<Rgb>* elem_color = nullptr; // solid colour per element (material plot)
};

struct RenderPanel {
    int x = 0, y = 0, w = 0, h = 0;  // viewport in output pixels, origin top-left
    Camera camera;
    Window window;
    RenderMesh mesh;
};

struct RenderStyle {
    bool edges = true;
    Rgb background{255, 255, 255};
    Rgb surface{215, 215, 215};   // unfringed faces
    Rgb edge{25, 25, 25};
    int bands = 10;
    int supersample = 2;          // render at this factor and box-filter down
    double edge_width = 1.0;      // output pixels
};

class Renderer {
public:
    Renderer();   // throws std::runtime_error when no OSMesa context can be made
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    Image render(int width, int height, const std::vector<RenderPanel>& panels, const RenderStyle& style);
    std::string gl_renderer() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace postimpact
