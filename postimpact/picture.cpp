#include "postimpact/picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "postimpact/elements.h"
#include "postimpact/fringe.h"

namespace postimpact {

namespace {

const Rgb kBlack{0, 0, 0};
const Rgb kText{20, 20, 20};

Rgb material_color(int m) {
    static const Rgb pal[] = {{70, 130, 200}, {220, 120, 50}, {90, 170, 90}, {200, 80, 90},
                              {150, 110, 190}, {140, 100, 70}, {210, 140, 190}, {150, 150, 150},
                              {190, 190, 60}, {60, 190, 200}};
    return pal[(m - 1 + 1000) % 10];
}

struct ShownState {
    int index = 0;
    std::vector<double> coords;        // possibly magnified displacement
    std::vector<SurfaceFace> faces;
    std::vector<double> node_vals, elem_vals;  // fringe values (one of them)
    std::vector<double> node_t, elem_t;
    std::vector<Rgb> elem_color;
};

// The 0-based node (node = true) or element index of a mark.
int find_marked(Database& db, const PictureMark& m, bool& node) {
    node = m.what == "node";
    int idx = -1;
    if (node) idx = db.node_index(m.id);
    else if (m.what == "elem" || m.what == "element") idx = db.element_index(m.id);
    else if (m.what == "solid") idx = db.element_index(m.id, static_cast<int>(Family::Solid));
    else if (m.what == "tshell" || m.what == "thick shell") idx = db.element_index(m.id, static_cast<int>(Family::ThickShell));
    else if (m.what == "beam") idx = db.element_index(m.id, static_cast<int>(Family::Beam));
    else if (m.what == "shell") idx = db.element_index(m.id, static_cast<int>(Family::Shell));
    else throw std::invalid_argument("mark: unknown kind '" + m.what + "' (node elem solid tshell beam shell)");
    if (idx < 0) throw std::invalid_argument("mark: no " + m.what + " " + std::to_string(m.id) + " in the database");
    return idx;
}

// Anti-aliased ring of radius r and line width w (pixels) around (cx, cy).
void draw_ring(Image& img, double cx, double cy, double r, double w, Rgb c) {
    const int x0 = static_cast<int>(std::floor(cx - r - w)), x1 = static_cast<int>(std::ceil(cx + r + w));
    const int y0 = static_cast<int>(std::floor(cy - r - w)), y1 = static_cast<int>(std::ceil(cy + r + w));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double d = std::hypot(x - cx, y - cy);
            const double cov = std::clamp(0.5 * w + 0.5 - std::fabs(d - r), 0.0, 1.0);
            if (cov > 0) img.blend(x, y, c, cov);
        }
}

// What the picture colours: a fringe quantity, the materials, or nothing.
struct Coloring {
    Quantity q;
    bool is_material = false;
    bool has_fringe = false;
    bool flat = false;  // element values drawn flat (not averaged to the nodes)
};

Coloring coloring_of(const PictureSettings& ps) {
    Coloring c;
    c.is_material = ps.fringe == "material";
    c.has_fringe = ps.fringe != "none" && !c.is_material;
    if (c.has_fringe && !find_quantity(ps.fringe, c.q))
        throw std::invalid_argument("unknown fringe quantity '" + ps.fringe + "' (one of: none material " + quantity_keys() + ")");
    c.flat = c.has_fringe && c.q.where == Quantity::Where::Element && !ps.average;
    return c;
}

// One state as drawn: coordinates (displacements magnified), faces, fringe values or colours.
ShownState build_state(Database& db, int si, const PictureSettings& ps, const Coloring& col) {
    const auto& g = db.geometry();
    ShownState s;
    s.index = si;
    const impact3d::PlotState& st = db.state(si);
    s.coords = st.coords.empty() ? g.x0 : st.coords;
    if (ps.deform_scale != 1.0)
        for (std::size_t i = 0; i < s.coords.size(); ++i) s.coords[i] = g.x0[i] + ps.deform_scale * (s.coords[i] - g.x0[i]);
    s.faces = drop_symmetry_faces(model_faces(g, st), g, ps.mirror);
    if (col.has_fringe) {
        if (col.flat) s.elem_vals = element_values(col.q, g, db.layout(), st);
        else s.node_vals = nodal_fringe(col.q, g, st, db.layout());
    }
    if (col.is_material) {
        s.elem_color.resize(static_cast<std::size_t>(num_elements(g)));
        for (int e = 0; e < num_elements(g); ++e) s.elem_color[e] = material_color(element_material(g, e));
    }
    return s;
}

// The largest and smallest raw value (element or node) over the shown states, with its index
// and state.
struct Extremes {
    bool found = false;
    double vmax = 0, vmin = 0;
    int vmax_id = 0, vmin_id = 0, vmax_state = 0, vmin_state = 0;
};

Extremes find_extremes(Database& db, const std::vector<ShownState>& ordered, const Quantity& q) {
    const auto& g = db.geometry();
    Extremes x;
    for (const auto& s : ordered) {
        const impact3d::PlotState& st = db.state(s.index);
        const bool elem = q.where == Quantity::Where::Element;
        const std::vector<double> v = elem ? element_values(q, g, db.layout(), st) : node_values(q, g, st);
        for (std::size_t i = 0; i < v.size(); ++i) {
            if (elem && !element_alive(st, g, static_cast<int>(i))) continue;
            if (!x.found || v[i] > x.vmax) { x.vmax = v[i]; x.vmax_id = static_cast<int>(i); x.vmax_state = s.index; }
            if (!x.found || v[i] < x.vmin) { x.vmin = v[i]; x.vmin_id = static_cast<int>(i); x.vmin_state = s.index; }
            x.found = true;
        }
    }
    return x;
}

// The shown states in the order asked, the window bounds and fringe range over the fit states,
// the extremes over the shown states, and each state's fringe coordinates in the range.
struct PreparedStates {
    std::vector<ShownState> ordered;
    Bounds bounds;
    FringeRange range;
    Extremes extremes;
};

PreparedStates prepare_states(Database& db, const std::vector<int>& states, const std::vector<int>& fit_states,
                              const PictureSettings& ps, const Coloring& col, const Camera& cam,
                              const std::vector<std::array<double, 3>>& copies) {
    PreparedStates out;
    bool have_range = false;
    std::vector<ShownState> shown;
    for (int si : fit_states) {
        ShownState s = build_state(db, si, ps, col);
        for (const auto& sg : copies)
            for (const auto& f : s.faces)
                for (int k = 0; k < f.count; ++k) {
                    const double* p = &s.coords[3 * f.nodes[k]];
                    const double r[3] = {sg[0] * p[0], sg[1] * p[1], sg[2] * p[2]};
                    out.bounds.add(cam, r);
                }
        if (col.has_fringe) extend_range(out.range, have_range, s.faces, s.node_vals, s.elem_vals);
        if (std::find(states.begin(), states.end(), si) != states.end()) shown.push_back(std::move(s));
    }
    // states not among the fit states
    for (int si : states)
        if (std::none_of(shown.begin(), shown.end(), [&](const ShownState& s) { return s.index == si; }))
            shown.push_back(build_state(db, si, ps, col));
    for (int si : states)
        for (auto& s : shown)
            if (s.index == si) { out.ordered.push_back(s); break; }
    if (col.has_fringe) out.extremes = find_extremes(db, out.ordered, col.q);
    FringeRange& range = out.range;
    if (!ps.range_auto) { range.lo = ps.range_lo; range.hi = ps.range_hi; }
    else if (have_range && range.hi - range.lo <= 1e-12 * std::max(std::fabs(range.hi), 1e-300)) {
        // constant field: a symmetric band around the value
        const double d = std::max(std::fabs(range.hi) * 0.01, 1e-12);
        range.lo -= d;
        range.hi += d;
    }
    for (auto& s : out.ordered) {
        if (!s.node_vals.empty()) { s.node_t.resize(s.node_vals.size()); for (std::size_t i = 0; i < s.node_vals.size(); ++i) s.node_t[i] = fringe_coord(s.node_vals[i], range); }
        if (!s.elem_vals.empty()) { s.elem_t.resize(s.elem_vals.size()); for (std::size_t i = 0; i < s.elem_vals.size(); ++i) s.elem_t[i] = fringe_coord(s.elem_vals[i], range); }
    }
    return out;
}

// Where things go on the image: text sizes, the header, the legend column, the drawing area
// and its panels (one per shown state).
struct PictureLayout {
    int W = 0, H = 0, unit = 0, title_px = 0, sub_px = 0, label_px = 0, margin = 0;
    bool show_legend = false, seq = false;
    int legend_w = 0, header = 0, caption = 0;
    int area_x = 0, area_y = 0, area_w = 0, area_h = 0;
    int n = 0, pw = 0;  // panels and their width
    double t_last = 0;  // the database's last time (time formats)
};

PictureLayout lay_out(Database& db, const PictureSettings& ps, const Coloring& col, int shown) {
    PictureLayout L;
    L.W = ps.width;
    L.H = ps.height;
    L.unit = std::max(8, std::min(L.W, L.H * 4 / 3) / 60);   // ~27 px at 1600x1200
    L.title_px = L.unit * 6 / 5;
    L.sub_px = L.unit * 9 / 10;
    L.label_px = L.unit * 3 / 4;
    L.margin = L.unit;
    L.t_last = db.num_states() ? db.time(db.num_states() - 1) : 0.0;
    L.show_legend = ps.legend && (col.has_fringe || col.is_material);
    L.legend_w = L.show_legend ? std::max(L.W / 6, L.unit * 8) : 0;
    L.header = L.margin + L.title_px + L.sub_px * 2;
    L.seq = shown > 1;
    L.caption = L.seq ? L.sub_px * 2 : 0;
    L.area_x = L.margin;
    L.area_y = L.header + L.margin / 2;
    L.area_w = L.W - L.legend_w - 2 * L.margin;
    L.area_h = L.H - L.area_y - L.margin - L.caption;
    if (L.area_w < 8 || L.area_h < 8) throw std::invalid_argument("picture: image too small");
    L.n = shown;
    L.pw = L.area_w / L.n;
    return L;
}

std::vector<RenderPanel> make_panels(const PictureLayout& L, const Camera& cam, const Window& win,
                                     const std::vector<ShownState>& ordered,
                                     const std::vector<std::array<double, 3>>& copies) {
    std::vector<RenderPanel> panels;
    for (int i = 0; i < L.n; ++i) {
        RenderPanel p;
        p.x = L.area_x + i * L.pw;
        p.y = L.area_y;
        p.w = L.pw;
        p.h = L.area_h;
        p.camera = cam;
        p.window = win;
        p.mesh.coords = &ordered[i].coords;
        p.mesh.faces = &ordered[i].faces;
        p.mesh.copies = copies;
        if (!ordered[i].node_t.empty()) p.mesh.node_t = &ordered[i].node_t;
        if (!ordered[i].elem_t.empty()) p.mesh.elem_t = &ordered[i].elem_t;
        if (!ordered[i].elem_color.empty()) p.mesh.elem_color = &ordered[i].elem_color;
        panels.push_back(p);
    }
    return panels;
}

// The title, the subtitle (what is shown, time and state or the number of states, mirroring,
// magnification) and, for a sequence, each panel's time.
void draw_titles(Image& img, Database& db, const PictureSettings& ps, const Coloring& col, const PictureLayout& L,
                 const std::vector<ShownState>& ordered, const Font& font) {
    std::string title = ps.title.empty() ? db.geometry().title : ps.title;
    while (!title.empty() && title.back() == ' ') title.pop_back();
    if (title.empty()) title = db.root();
    font.draw(img, L.margin, L.margin + font.ascent(L.title_px), title, L.title_px, kText);
    std::string sub = col.has_fringe ? col.q.label : (col.is_material ? std::string("Materials") : std::string("Deformed shape"));
    if (!L.seq) {
        const int si = ordered[0].index;
        sub += "     t = " + format_time(db.time(si), L.t_last, ps.units) + "     state " +
               std::to_string(si + 1) + " of " + std::to_string(db.num_states());
    } else {
        sub += "     " + std::to_string(L.n) + " states";
    }
    if (ps.mirror.any()) sub += "     mirrored " + mirror_name(ps.mirror);
    if (ps.deform_scale != 1.0) {
        char b[64];
        std::snprintf(b, sizeof b, "     displacements x %g", ps.deform_scale);
        sub += b;
    }
    font.draw(img, L.margin, L.margin + L.title_px + L.sub_px / 2 + font.ascent(L.sub_px), sub, L.sub_px, {60, 60, 60});
    if (L.seq)
        for (int i = 0; i < L.n; ++i) {
            const int si = ordered[i].index;
            const std::string cap = format_time(db.time(si), L.t_last, ps.units);
            font.draw(img, L.area_x + i * L.pw + L.pw / 2, L.area_y + L.area_h + L.sub_px + L.sub_px / 2, cap, L.sub_px, kText,
                      HAlign::Center);
        }
}

// `text` broken into lines on spaces, each at most `width` pixels at size px where a word
// allows (`skip_empty`: runs of spaces count as one).
std::vector<std::string> wrap_words(const std::string& text, const Font& font, int px, int width, bool skip_empty) {
    std::vector<std::string> lines;
    std::string cur, word;
    for (char c : text + " ") {
        if (c != ' ') { word += c; continue; }
        if (skip_empty && word.empty()) continue;
        const std::string trial = cur.empty() ? word : cur + " " + word;
        if (!cur.empty() && font.measure(trial, px) > width) { lines.push_back(cur); cur = word; }
        else cur = trial;
        word.clear();
    }
    if (!cur.empty()) lines.push_back(cur);
    return lines;
}

// The fringe legend: the quantity and its unit, the colour bar with its values, the extremes
// with the node or element (and time, for a sequence) where they are.
void draw_fringe_legend(Image& img, Database& db, const PictureSettings& ps, const Coloring& col, const PictureLayout& L,
                        const FringeRange& range, const Extremes& x, const Font& font) {
    const int unit = L.unit, label_px = L.label_px;
    const int lx = L.W - L.legend_w - L.margin / 2;
    int y = L.area_y + unit;
    const DisplayUnit du = display_unit(col.q.dim, std::max(std::fabs(range.lo), std::fabs(range.hi)), ps.units);
    // quantity label, wrapped on words to the legend width
    std::vector<std::string> lines = wrap_words(col.q.label, font, L.sub_px, L.legend_w, false);
    if (!du.name.empty()) lines.push_back("(" + du.name + ")");
    for (const auto& l : lines) {
        y += font.ascent(L.sub_px);
        font.draw(img, lx, y, l, L.sub_px, kText);
        y += font.descent(L.sub_px) + 2;
    }
    y += unit / 2;
    const int bar_w = unit * 3 / 2;
    const int bar_h = std::max(L.area_h / 2, ps.bands * 8);
    const int nb = std::max(1, ps.bands);
    const double step = (range.hi - range.lo) * du.factor / nb;
    for (int i = 0; i < nb; ++i) {
        const int y0 = y + bar_h - (i + 1) * bar_h / nb, y1 = y + bar_h - i * bar_h / nb;
        img.fill_rect(lx, y0, lx + bar_w, y1, band_color(i, nb));
    }
    img.rect_outline(lx - 1, y - 1, lx + bar_w + 1, y + bar_h + 1, kBlack);
    for (int i = 0; i <= nb; ++i) {
        const int yy = y + bar_h - i * bar_h / nb;
        img.fill_rect(lx + bar_w, yy, lx + bar_w + unit / 3, yy + 1, kBlack);
        const double v = (range.lo + (range.hi - range.lo) * i / nb) * du.factor;
        font.draw(img, lx + bar_w + unit / 2, yy + font.ascent(label_px) * 2 / 5, format_number(v, step), label_px, kText);
    }
    y += bar_h + unit;
    if (!x.found) return;
    const auto& g = db.geometry();
    const bool elem = col.q.where == Quantity::Where::Element;
    auto ext = [&](const char* what, double v, int id, int st) {
        std::string s = std::string(what) + " " + format_number(v * du.factor, step);
        y += font.ascent(label_px);
        font.draw(img, lx, y, s, label_px, kText);
        y += font.descent(label_px) + 2;
        const Family fam = elem ? element_ref(g, id).family : Family::Solid;
        std::string w = (elem ? (fam == Family::Solid ? std::string("elem") : std::string(family_name(fam))) + " " +
                                    std::to_string(db.element_id(id))
                              : "node " + std::to_string(db.node_id(id)));
        if (L.seq) w += ", " + format_time(db.time(st), L.t_last, ps.units);
        y += font.ascent(label_px);
        font.draw(img, lx + unit / 2, y, w, label_px, {70, 70, 70});
        y += font.descent(label_px) + unit / 3;
    };
    ext("max", x.vmax, x.vmax_id, x.vmax_state);
    ext("min", x.vmin, x.vmin_id, x.vmin_state);
}

// The material legend: a swatch per material and its part name, wrapped on words to the legend
// column (long titles were cut off).
void draw_material_legend(Image& img, Database& db, const PictureLayout& L, const Font& font) {
    const int unit = L.unit, label_px = L.label_px;
    const int lx = L.W - L.legend_w - L.margin / 2;
    int y = L.area_y + unit;
    const int tx = lx + unit * 3 / 2, text_w = L.W - L.margin / 2 - tx;
    for (int m = 1; m <= db.geometry().num_materials; ++m) {
        img.fill_rect(lx, y, lx + unit, y + unit, material_color(m));
        img.rect_outline(lx, y, lx + unit, y + unit, kBlack);
        const std::vector<std::string> lines = wrap_words(db.part_name(m), font, label_px, text_w, true);
        const int line_h = font.ascent(label_px) + font.descent(label_px) + 2;
        int ty = y + unit - 3;
        for (const auto& l : lines) {
            font.draw(img, tx, ty, l, label_px, kText);
            ty += line_h;
        }
        y += std::max(unit * 3 / 2, unit + line_h * (static_cast<int>(lines.size()) - 1) + unit / 2);
    }
}

// The axis triad: in the legend column when there is one (it never covers the model), else
// bottom left.
void draw_triad(Image& img, const Camera& cam, const PictureLayout& L, const Font& font) {
    const int unit = L.unit, label_px = L.label_px;
    const int len = unit * 2;
    const int ox = L.show_legend ? L.W - L.legend_w / 2 - L.margin / 2 : L.margin + len + unit / 2;
    const int oy = L.H - L.margin - len - L.caption;
    const char* names[3] = {"x", "y", "z"};
    const Rgb cols[3] = {{200, 30, 30}, {30, 150, 30}, {30, 60, 210}};
    for (int a = 0; a < 3; ++a) {
        double e[3] = {0, 0, 0};
        e[a] = 1.0;
        const double dx = cam.sx(e), dy = -cam.sy(e);
        if (std::hypot(dx, dy) < 0.05) {
            font.draw(img, ox + 4, oy - 4, names[a], label_px, cols[a]);
            continue;
        }
        img.line(ox, oy, ox + dx * len, oy + dy * len, cols[a], 2.0);
        font.draw(img, static_cast<int>(ox + dx * (len + unit / 2)), static_cast<int>(oy + dy * (len + unit / 2)) + label_px / 3,
                  names[a], label_px, cols[a], HAlign::Center);
    }
}

// The marks: a ring with four ticks at the projected node / element centroid in every panel, and
// a label; their pixel positions in `spots` when asked.
void draw_marks(Image& img, Database& db, const PictureSettings& ps, const PictureLayout& L, const Camera& cam,
                const Window& win, const std::vector<ShownState>& ordered, const std::vector<RenderPanel>& panels,
                const Font& font, std::vector<MarkSpot>* spots) {
    const auto& g = db.geometry();
    const int unit = L.unit, label_px = L.label_px;
    if (spots) spots->clear();
    for (const PictureMark& m : ps.marks) {
        bool node = false;
        const int idx = find_marked(db, m, node);
        const std::string label = m.label.empty() ? m.what + " " + std::to_string(m.id) : m.label;
        for (int i = 0; i < L.n; ++i) {
            const std::vector<double>& X = ordered[i].coords;
            double c[3] = {0, 0, 0};
            if (node) {
                for (int k = 0; k < 3; ++k) c[k] = X[3 * static_cast<std::size_t>(idx) + k];
            } else {
                int count = 0;
                const int* en = element_nodes(g, idx, count);
                for (int j = 0; j < count; ++j)
                    for (int k = 0; k < 3; ++k) c[k] += X[3 * static_cast<std::size_t>(en[j]) + k] / count;
            }
            const RenderPanel& p = panels[static_cast<std::size_t>(i)];
            // glOrtho's window onto the panel's pixels (pixel centres at +0.5)
            const double px = p.x + (cam.sx(c) - (win.cx - win.half_w)) / (2 * win.half_w) * p.w - 0.5;
            const double py = p.y + ((win.cy + win.half_h) - cam.sy(c)) / (2 * win.half_h) * p.h - 0.5;
            const double r = unit * 1.2, lw = std::max(2.0, unit / 4.0);
            draw_ring(img, px, py, r, lw, kMarkColor);
            for (int a = 0; a < 4; ++a) {
                const double dx = a == 0 ? 1 : a == 1 ? -1 : 0, dy = a == 2 ? 1 : a == 3 ? -1 : 0;
                img.line(px + dx * (r + lw), py + dy * (r + lw), px + dx * (r + lw + unit * 0.6), py + dy * (r + lw + unit * 0.6),
                         kMarkColor, lw);
            }
            // the label on a white box above right of the ring (dark magenta: never mistaken for the ring)
            const int tx = static_cast<int>(px + r + unit * 0.6), ty = static_cast<int>(py - r - unit * 0.4);
            const int tw = font.measure(label, label_px);
            img.fill_rect(tx - 2, ty - font.ascent(label_px) - 2, tx + tw + 3, ty + font.descent(label_px) + 2, {255, 255, 255});
            font.draw(img, tx, ty, label, label_px, {130, 0, 130});
            if (spots) spots->push_back({px, py, i});
        }
    }
}

}  // namespace

Image make_picture(Database& db, const std::vector<int>& states, const PictureSettings& ps,
                   Renderer& renderer, const Font& font, const std::vector<int>& fit_states0,
                   std::vector<MarkSpot>* spots) {
    if (states.empty()) throw std::invalid_argument("picture: no state");
    const std::vector<int>& fit_states = fit_states0.empty() ? states : fit_states0;
    const Coloring col = coloring_of(ps);
    const Camera cam = make_camera(ps.view);
    const auto copies = mirror_copies(ps.mirror);
    const PreparedStates prep = prepare_states(db, states, fit_states, ps, col, cam, copies);

    const PictureLayout L = lay_out(db, ps, col, static_cast<int>(prep.ordered.size()));
    const Window win = fit_window(prep.bounds, L.pw, L.area_h, L.seq ? 0.04 : 0.06);
    RenderStyle style;
    style.edges = ps.edges;
    style.bands = ps.bands;
    style.supersample = ps.supersample;
    const std::vector<RenderPanel> panels = make_panels(L, cam, win, prep.ordered, copies);
    Image img = renderer.render(L.W, L.H, panels, style);

    draw_titles(img, db, ps, col, L, prep.ordered, font);
    if (L.show_legend && col.has_fringe) draw_fringe_legend(img, db, ps, col, L, prep.range, prep.extremes, font);
    else if (L.show_legend && col.is_material) draw_material_legend(img, db, L, font);
    if (ps.triad) draw_triad(img, cam, L, font);
    draw_marks(img, db, ps, L, cam, win, prep.ordered, panels, font, spots);
    return img;
}

}  // namespace postimpact
