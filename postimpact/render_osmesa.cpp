#include "postimpact/render_osmesa.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <cmath>
#include <stdexcept>

#include "postimpact/fringe.h"

namespace postimpact {

struct Renderer::Impl {
    OSMesaContext ctx = nullptr;
    std::vector<std::uint8_t> buffer;
    GLuint tex = 0;
    std::vector<float> pos, nrm, tc, col, lines;
    std::vector<float> beam_pos, beam_tc, beam_col;  // beams (faces of count 2): thick lines
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

}  // namespace

Image Renderer::render(int width, int height, const std::vector<RenderPanel>& panels,
                       const RenderStyle& style) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("render: empty image size");
    const int ss = std::max(1, style.supersample);
    const int W = width * ss, H = height * ss;
    Impl& m = *impl_;
    m.buffer.resize(4 * static_cast<std::size_t>(W) * H);  // every pixel is cleared below
    if (!OSMesaMakeCurrent(m.ctx, m.buffer.data(), GL_UNSIGNED_BYTE, W, H))
        throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(W) + "x" + std::to_string(H) + " buffer");
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 of the buffer = top of the picture

    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, W, H);
    glClearColor(style.background.r / 255.f, style.background.g / 255.f, style.background.b / 255.f, 1.f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // fringe band texture
    if (!m.tex) glGenTextures(1, &m.tex);
    const int nb = std::max(1, style.bands);
    std::vector<std::uint8_t> texels(3 * nb);
    for (int i = 0; i < nb; ++i) {
        const Rgb c = band_color(i, nb);
        texels[3 * i] = c.r; texels[3 * i + 1] = c.g; texels[3 * i + 2] = c.b;
    }
    glBindTexture(GL_TEXTURE_1D, m.tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, nb, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

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

    for (const RenderPanel& p : panels) {
        const RenderMesh& rm = p.mesh;
        if (!rm.coords || !rm.faces) continue;
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

        // vertex arrays: flat-shaded triangles (face normal), fringe coordinate per vertex
        const bool textured = rm.node_t || rm.elem_t;
        m.pos.clear(); m.nrm.clear(); m.tc.clear(); m.col.clear(); m.lines.clear();
        m.beam_pos.clear(); m.beam_tc.clear(); m.beam_col.clear();
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
                if (f.count == 2) {
                    const Rgb bc = rm.elem_color ? (*rm.elem_color)[f.element] : style.edge;
                    for (int k = 0; k < 2; ++k) {
                        m.beam_pos.insert(m.beam_pos.end(), {q[3 * k], q[3 * k + 1], q[3 * k + 2]});
                        m.beam_tc.push_back(std::min(t[k], 0.99999f));
                        m.beam_col.insert(m.beam_col.end(), {bc.r / 255.f, bc.g / 255.f, bc.b / 255.f});
                    }
                    continue;
                }
                float n[3];
                face_normal(q, f.count, n);
                const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
                Rgb ec = style.surface;
                if (rm.elem_color) ec = (*rm.elem_color)[f.element];
                for (int ti = 0; ti < (f.count == 4 ? 2 : 1); ++ti)
                    for (int k : tri[ti]) {
                        m.pos.insert(m.pos.end(), {q[3 * k], q[3 * k + 1], q[3 * k + 2]});
                        m.nrm.insert(m.nrm.end(), {n[0], n[1], n[2]});
                        // texel centre convention: t in [0,1] maps onto the nb bands
                        m.tc.push_back(std::min(t[k], 0.99999f));
                        m.col.insert(m.col.end(), {ec.r / 255.f, ec.g / 255.f, ec.b / 255.f});
                    }
                if (style.edges)
                    for (int k = 0; k < f.count; ++k) {
                        const int k2 = (k + 1) % f.count;
                        m.lines.insert(m.lines.end(), {q[3 * k], q[3 * k + 1], q[3 * k + 2],
                                                       q[3 * k2], q[3 * k2 + 1], q[3 * k2 + 2]});
                    }
            }
        }
        glEnable(GL_LIGHTING);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, m.pos.data());
        glNormalPointer(GL_FLOAT, 0, m.nrm.data());
        if (textured) {
            glEnable(GL_TEXTURE_1D);
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glTexCoordPointer(1, GL_FLOAT, 0, m.tc.data());
            glDisableClientState(GL_COLOR_ARRAY);
            glColor3f(1.f, 1.f, 1.f);
        } else {
            glColorPointer(3, GL_FLOAT, 0, m.col.data());
        }
        glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(m.pos.size() / 3));
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glDisableClientState(GL_NORMAL_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisable(GL_TEXTURE_1D);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_LIGHTING);
        if (!m.beam_pos.empty()) {
            glLineWidth(static_cast<GLfloat>(3.0 * ss));
            glVertexPointer(3, GL_FLOAT, 0, m.beam_pos.data());
            if (textured) {
                glEnable(GL_TEXTURE_1D);
                glEnableClientState(GL_TEXTURE_COORD_ARRAY);
                glTexCoordPointer(1, GL_FLOAT, 0, m.beam_tc.data());
                glColor3f(1.f, 1.f, 1.f);
            } else {
                glEnableClientState(GL_COLOR_ARRAY);
                glColorPointer(3, GL_FLOAT, 0, m.beam_col.data());
            }
            glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(m.beam_pos.size() / 3));
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            glDisableClientState(GL_COLOR_ARRAY);
            glDisable(GL_TEXTURE_1D);
        }
        if (style.edges && !m.lines.empty()) {
            glLineWidth(static_cast<GLfloat>(style.edge_width * ss));
            glColor3f(style.edge.r / 255.f, style.edge.g / 255.f, style.edge.b / 255.f);
            glVertexPointer(3, GL_FLOAT, 0, m.lines.data());
            glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(m.lines.size() / 3));
        }
        glDisableClientState(GL_VERTEX_ARRAY);
    }
    glFinish();

    // box-filter the supersampled buffer straight into the output image (alpha: opaque)
    Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(4 * static_cast<std::size_t>(width) * height);
    const std::uint8_t* src = m.buffer.data();
    const std::size_t row = 4 * static_cast<std::size_t>(W);
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

}  // namespace postimpact
