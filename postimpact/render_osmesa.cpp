#include "postimpact/render_osmesa.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <cmath>
#include <stdexcept>

#include "postimpact/fringe.h"

namespace postimpact {

namespace {

// The vertex arrays of one panel, refilled for each panel (capacity kept between pictures).
struct PanelArrays {
    std::vector<float> pos, nrm, tc, col, lines;
    std::vector<float> beam_pos, beam_tc, beam_col;  // beams (faces of count 2): thick lines

    void clear() {
        pos.clear(); nrm.clear(); tc.clear(); col.clear(); lines.clear();
        beam_pos.clear(); beam_tc.clear(); beam_col.clear();
    }
};

}  // namespace

struct Renderer::Impl {
    OSMesaContext ctx = nullptr;
    std::vector<std::uint8_t> buffer;
    GLuint tex = 0;
    PanelArrays arrays;
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
    impl_->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!impl_->ctx) throw std::runtime_error("OSMesa: cannot create an offscreen OpenGL context");
}

Renderer::~Renderer() {
    if (impl_ && impl_->ctx) OSMesaDestroyContext(impl_->ctx);
}

std::string Renderer::gl_renderer() const {
    const GLubyte* s = glGetString(GL_RENDERER);
    return s ? reinterpret_cast<const char*>(s) : "?";
}

namespace {

void face_normal(const float* p, int n, float* out) {
    // Newell's method (robust for non-planar quads and triangles)
    double nx = 0, ny = 0, nz = 0;
    for (int k = 0; k < n; ++k) {
        const float* a = p + 3 * k;
        const float* b = p + 3 * ((k + 1) % n);
        nx += (a[1] - b[1]) * (a[2] + b[2]);
        ny += (a[2] - b[2]) * (a[0] + b[0]);
        nz += (a[0] - b[0]) * (a[1] + b[1]);
    }
    const double l = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (l > 0) { nx /= l; ny /= l; nz /= l; }
    out[0] = static_cast<float>(nx); out[1] = static_cast<float>(ny); out[2] = static_cast<float>(nz);
}

// Binds the (supersampled) W x H buffer to the context and clears it to the background.
void bind_and_clear_buffer(OSMesaContext ctx, std::vector<std::uint8_t>& buffer, int W, int H, const RenderStyle& style) {
    buffer.resize(4 * static_cast<std::size_t>(W) * H);  // every pixel is cleared below
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, W, H))
        throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(W) + "x" + std::to_string(H) + " buffer");
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 of the buffer = top of the picture

    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, W, H);
    glClearColor(style.background.r / 255.f, style.background.g / 255.f, style.background.b / 255.f, 1.f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// The fringe bands as a 1D texture of nb texels, sampled nearest (sharp band edges).
void load_band_texture(GLuint& tex, int bands) {
    if (!tex) glGenTextures(1, &tex);
    const int nb = std::max(1, bands);
    std::vector<std::uint8_t> texels(3 * nb);
    for (int i = 0; i < nb; ++i) {
        const Rgb c = band_color(i, nb);
        texels[3 * i] = c.r; texels[3 * i + 1] = c.g; texels[3 * i + 2] = c.b;
    }
    glBindTexture(GL_TEXTURE_1D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, nb, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
}

// Depth test, smooth shading and one two-sided light from the upper left front.
void set_depth_and_lighting() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_NORMALIZE);
    const GLfloat amb[4] = {0.38f, 0.38f, 0.38f, 1.f};
    const GLfloat dif[4] = {0.68f, 0.68f, 0.68f, 1.f};
    const GLfloat zero[4] = {0.f, 0.f, 0.f, 1.f};
    const GLfloat lpos[4] = {-0.35f, 0.45f, 1.0f, 0.f};  // eye space: from upper left, front
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, dif);
    glLightfv(GL_LIGHT0, GL_SPECULAR, zero);
    glLightfv(GL_LIGHT0, GL_POSITION, lpos);
    glEnable(GL_LIGHT0);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
}

// The panel's viewport (in the supersampled buffer of height H), orthographic window and camera.
void set_panel_view(const RenderPanel& p, int ss, int H) {
    const int vx = p.x * ss, vy = H - (p.y + p.h) * ss;
    glViewport(vx, vy, p.w * ss, p.h * ss);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    const Window& w = p.window;
    glOrtho(w.cx - w.half_w, w.cx + w.half_w, w.cy - w.half_h, w.cy + w.half_h, -w.dmax, -w.dmin);
    glMatrixMode(GL_MODELVIEW);
    const Camera& c = p.camera;
    const GLdouble mv[16] = {c.right[0], c.up[0], c.eye[0], 0, c.right[1], c.up[1], c.eye[1], 0,
                             c.right[2], c.up[2], c.eye[2], 0, 0, 0, 0, 1};
    glLoadMatrixd(mv);
}

// A beam (face of two nodes): a thick line, fringe coordinate or element colour per vertex.
void add_beam_face(const float* q, const float* t, const Rgb& bc, PanelArrays& a) {
    for (int k = 0; k < 2; ++k) {
        a.beam_pos.insert(a.beam_pos.end(), {q[3 * k], q[3 * k + 1], q[3 * k + 2]});
        a.beam_tc.push_back(std::min(t[k], 0.99999f));
        a.beam_col.insert(a.beam_col.end(), {bc.r / 255.f, bc.g / 255.f, bc.b / 255.f});
    }
}

// A triangle or quadrilateral face: flat-shaded triangles (face normal) and, with edges, its outline.
void add_surface_face(const float* q, const float* t, int count, const Rgb& ec, bool edges, PanelArrays& a) {
    float n[3];
    face_normal(q, count, n);
    const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (int ti = 0; ti < (count == 4 ? 2 : 1); ++ti)
        for (int k : tri[ti]) {
            a.pos.insert(a.pos.end(), {q[3 * k], q[3 * k + 1], q[3 * k + 2]});
            a.nrm.insert(a.nrm.end(), {n[0], n[1], n[2]});
            // texel centre convention: t in [0,1] maps onto the nb bands
            a.tc.push_back(std::min(t[k], 0.99999f));
            a.col.insert(a.col.end(), {ec.r / 255.f, ec.g / 255.f, ec.b / 255.f});
        }
    if (!edges) return;
    for (int k = 0; k < count; ++k) {
        const int k2 = (k + 1) % count;
        a.lines.insert(a.lines.end(), {q[3 * k], q[3 * k + 1], q[3 * k + 2], q[3 * k2], q[3 * k2 + 1], q[3 * k2 + 2]});
    }
}

// The vertex arrays of a mesh and its mirror copies (a mirrored copy reverses each face's order).
void fill_panel_arrays(const RenderMesh& rm, const RenderStyle& style, PanelArrays& a) {
    a.clear();
    const auto& X = *rm.coords;
    for (const auto& sgn : rm.copies) {
        const bool flip = (sgn[0] * sgn[1] * sgn[2]) < 0;
        for (const SurfaceFace& f : *rm.faces) {
            float q[12], t[4];
            for (int k = 0; k < f.count; ++k) {
                const int kk = flip ? (f.count - 1 - k) : k;
                const int node = f.nodes[kk];
                for (int d = 0; d < 3; ++d) q[3 * k + d] = static_cast<float>(sgn[d] * X[3 * node + d]);
                t[k] = rm.node_t ? static_cast<float>((*rm.node_t)[node])
                                 : (rm.elem_t ? static_cast<float>((*rm.elem_t)[f.element]) : 0.f);
            }
            if (f.count == 2) add_beam_face(q, t, rm.elem_color ? (*rm.elem_color)[f.element] : style.edge, a);
            else add_surface_face(q, t, f.count, rm.elem_color ? (*rm.elem_color)[f.element] : style.surface, style.edges, a);
        }
    }
}

// The faces, lit, with the band texture (fringes) or the per-vertex colours; offset behind the lines.
void draw_faces(const PanelArrays& a, bool textured) {
    glEnable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, a.pos.data());
    glNormalPointer(GL_FLOAT, 0, a.nrm.data());
    if (textured) {
        glEnable(GL_TEXTURE_1D);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(1, GL_FLOAT, 0, a.tc.data());
        glDisableClientState(GL_COLOR_ARRAY);
        glColor3f(1.f, 1.f, 1.f);
    } else {
        glColorPointer(3, GL_FLOAT, 0, a.col.data());
    }
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(a.pos.size() / 3));
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisable(GL_TEXTURE_1D);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_LIGHTING);
}

// The beams as lines three (supersampled) pixels wide, unlit.
void draw_beams(const PanelArrays& a, bool textured, int ss) {
    if (a.beam_pos.empty()) return;
    glLineWidth(static_cast<GLfloat>(3.0 * ss));
    glVertexPointer(3, GL_FLOAT, 0, a.beam_pos.data());
    if (textured) {
        glEnable(GL_TEXTURE_1D);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glTexCoordPointer(1, GL_FLOAT, 0, a.beam_tc.data());
        glColor3f(1.f, 1.f, 1.f);
    } else {
        glEnableClientState(GL_COLOR_ARRAY);
        glColorPointer(3, GL_FLOAT, 0, a.beam_col.data());
    }
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(a.beam_pos.size() / 3));
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisable(GL_TEXTURE_1D);
}

// The element edges in the edge colour.
void draw_edges(const PanelArrays& a, const RenderStyle& style, int ss) {
    if (!style.edges || a.lines.empty()) return;
    glLineWidth(static_cast<GLfloat>(style.edge_width * ss));
    glColor3f(style.edge.r / 255.f, style.edge.g / 255.f, style.edge.b / 255.f);
    glVertexPointer(3, GL_FLOAT, 0, a.lines.data());
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(a.lines.size() / 3));
}

// Box-filters the supersampled buffer (ss x ss pixels a pixel) into the output image (alpha: opaque).
Image downsample_buffer(const std::vector<std::uint8_t>& buffer, int width, int height, int ss) {
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(4 * static_cast<std::size_t>(width) * height);
    const std::uint8_t* src = buffer.data();
    const std::size_t row = 4 * static_cast<std::size_t>(width) * ss;
    const unsigned n = static_cast<unsigned>(ss * ss);
    for (int y = 0; y < height; ++y) {
        std::uint8_t* d = &img.rgba[4 * static_cast<std::size_t>(y) * width];
        for (int x = 0; x < width; ++x, d += 4) {
            unsigned r = 0, g = 0, b = 0;
            for (int j = 0; j < ss; ++j) {
                const std::uint8_t* p = src + (static_cast<std::size_t>(y) * ss + j) * row + 4 * static_cast<std::size_t>(x) * ss;
                for (int i = 0; i < ss; ++i, p += 4) { r += p[0]; g += p[1]; b += p[2]; }
            }
            d[0] = static_cast<std::uint8_t>((r + n / 2) / n);
            d[1] = static_cast<std::uint8_t>((g + n / 2) / n);
            d[2] = static_cast<std::uint8_t>((b + n / 2) / n);
            d[3] = 255;
        }
    }
    return img;
}

}  // namespace

Image Renderer::render(int width, int height, const std::vector<RenderPanel>& panels,
                       const RenderStyle& style) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("render: empty image size");
    const int ss = std::max(1, style.supersample);
    const int H = height * ss;
    Impl& m = *impl_;
    bind_and_clear_buffer(m.ctx, m.buffer, width * ss, H, style);
    load_band_texture(m.tex, style.bands);
    set_depth_and_lighting();
    for (const RenderPanel& p : panels) {
        const RenderMesh& rm = p.mesh;
        if (!rm.coords || !rm.faces) continue;
        set_panel_view(p, ss, H);
        fill_panel_arrays(rm, style, m.arrays);
        const bool textured = rm.node_t || rm.elem_t;
        draw_faces(m.arrays, textured);
        draw_beams(m.arrays, textured, ss);
        draw_edges(m.arrays, style, ss);
        glDisableClientState(GL_VERTEX_ARRAY);
    }
    glFinish();
    return downsample_buffer(m.buffer, width, height, ss);
}

}  // namespace postimpact
