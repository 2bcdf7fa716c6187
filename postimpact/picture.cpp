#include "postimpact/picture.h"

#include <algorithm>
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

}  // namespace

Image make_picture(Database& db, const std::vector<int>& states, const PictureSettings& ps,
                   Renderer& renderer, const Font& font, const std::vector<int>& fit_states0,
                   std::vector<MarkSpot>* spots) {
    if (states.empty()) throw std::invalid_argument("picture: no state");
    const auto& g = db.geometry();
    const std::vector<int>& fit_states = fit_states0.empty() ? states : fit_states0;
    Quantity q;
    const bool is_material = ps.fringe == "material";
    const bool has_fringe = ps.fringe != "none" && !is_material;
    if (has_fringe && !find_quantity(ps.fringe, q))
        throw std::invalid_argument("unknown fringe quantity '" + ps.fringe + "' (one of: none material " + quantity_keys() + ")");
    const bool flat = has_fringe && q.where == Quantity::Where::Element && !ps.average;
    const Camera cam = make_camera(ps.view);
    const auto copies = mirror_copies(ps.mirror);

    auto build = [&](int si) {
        ShownState s;
        s.index = si;
        const impact3d::PlotState& st = db.state(si);
        s.coords = st.coords.empty() ? g.x0 : st.coords;
        if (ps.deform_scale != 1.0)
            for (std::size_t i = 0; i < s.coords.size(); ++i) s.coords[i] = g.x0[i] + ps.deform_scale * (s.coords[i] - g.x0[i]);
        s.faces = drop_symmetry_faces(model_faces(g, st), g, ps.mirror);
        if (has_fringe) {
            if (flat) s.elem_vals = element_values(q, g, db.layout(), st);
            else s.node_vals = nodal_fringe(q, g, st, db.layout());
        }
        if (is_material) {
            s.elem_color.resize(static_cast<std::size_t>(num_elements(g)));
            for (int e = 0; e < num_elements(g); ++e) s.elem_color[e] = material_color(element_material(g, e));
        }
        return s;
    };

    // window and fringe range from the fit states
    Bounds bounds;
    FringeRange range;
    bool have_range = false;
    double vmax = 0, vmin = 0; int vmax_id = 0, vmin_id = 0, vmax_state = 0, vmin_state = 0;
    bool have_extreme = false;
    std::vector<ShownState> shown;
    for (int si : fit_states) {
        ShownState s = build(si);
        for (const auto& sg : copies)
            for (const auto& f : s.faces)
                for (int k = 0; k < f.count; ++k) {
                    const double* p = &s.coords[3 * f.nodes[k]];
                    const double r[3] = {sg[0] * p[0], sg[1] * p[1], sg[2] * p[2]};
                    bounds.add(cam, r);
                }
        if (has_fringe) extend_range(range, have_range, s.faces, s.node_vals, s.elem_vals);
        if (std::find(states.begin(), states.end(), si) != states.end()) shown.push_back(std::move(s));
    }
    // states not among the fit states
    for (int si : states)
        if (std::none_of(shown.begin(), shown.end(), [&](const ShownState& s) { return s.index == si; }))
            shown.push_back(build(si));
    std::vector<ShownState> ordered;
    for (int si : states)
        for (auto& s : shown)
            if (s.index == si) { ordered.push_back(s); break; }
    // extremes of the raw values (element or node) over the shown states, with ids
    if (has_fringe)
        for (const auto& s : ordered) {
            const impact3d::PlotState& st = db.state(s.index);
            const bool elem = q.where == Quantity::Where::Element;
            const std::vector<double> v = elem ? element_values(q, g, db.layout(), st) : node_values(q, g, st);
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (elem && !element_alive(st, g, static_cast<int>(i))) continue;
                if (!have_extreme || v[i] > vmax) { vmax = v[i]; vmax_id = static_cast<int>(i); vmax_state = s.index; }
                if (!have_extreme || v[i] < vmin) { vmin = v[i]; vmin_id = static_cast<int>(i); vmin_state = s.index; }
                have_extreme = true;
            }
        }
    if (!ps.range_auto) { range.lo = ps.range_lo; range.hi = ps.range_hi; }
    else if (have_range && range.hi - range.lo <= 1e-12 * std::max(std::fabs(range.hi), 1e-300)) {
        // constant field: a symmetric band around the value
        const double d = std::max(std::fabs(range.hi) * 0.01, 1e-12);
        range.lo -= d;
        range.hi += d;
    }
    for (auto& s : ordered) {
        if (!s.node_vals.empty()) { s.node_t.resize(s.node_vals.size()); for (std::size_t i = 0; i < s.node_vals.size(); ++i) s.node_t[i] = fringe_coord(s.node_vals[i], range); }
        if (!s.elem_vals.empty()) { s.elem_t.resize(s.elem_vals.size()); for (std::size_t i = 0; i < s.elem_vals.size(); ++i) s.elem_t[i] = fringe_coord(s.elem_vals[i], range); }
    }

    // ---- layout
    const int W = ps.width, H = ps.height;
    const int unit = std::max(8, std::min(W, H * 4 / 3) / 60);   // ~27 px at 1600x1200
    const int title_px = unit * 6 / 5, sub_px = unit * 9 / 10, label_px = unit * 3 / 4;
    const int margin = unit;
    const double t_last = db.num_states() ? db.time(db.num_states() - 1) : 0.0;
    const bool show_legend = ps.legend && (has_fringe || is_material);
    const int legend_w = show_legend ? std::max(W / 6, unit * 8) : 0;
    const int header = margin + title_px + sub_px * 2;
    const bool seq = ordered.size() > 1;
    const int caption = seq ? sub_px * 2 : 0;
    const int area_x = margin, area_y = header + margin / 2;
    const int area_w = W - legend_w - 2 * margin, area_h = H - area_y - margin - caption;
    if (area_w < 8 || area_h < 8) throw std::invalid_argument("picture: image too small");

    const int n = static_cast<int>(ordered.size());
    const int pw = area_w / n;
    const Window win = fit_window(bounds, pw, area_h, seq ? 0.04 : 0.06);
    RenderStyle style;
    style.edges = ps.edges;
    style.bands = ps.bands;
    style.supersample = ps.supersample;
    std::vector<RenderPanel> panels;
    for (int i = 0; i < n; ++i) {
        RenderPanel p;
        p.x = area_x + i * pw;
        p.y = area_y;
        p.w = pw;
        p.h = area_h;
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
    Image img = renderer.render(W, H, panels, style);

    // ---- text: title and subtitle
    std::string title = ps.title.empty() ? g.title : ps.title;
    while (!title.empty() && title.back() == ' ') title.pop_back();
    if (title.empty()) title = db.root();
    font.draw(img, margin, margin + font.ascent(title_px), title, title_px, kText);
    std::string sub = has_fringe ? q.label : (is_material ? std::string("Materials") : std::string("Deformed shape"));
    if (!seq) {
        const int si = ordered[0].index;
        sub += "     t = " + format_time(db.time(si), t_last, ps.units) + "     state " +
               std::to_string(si + 1) + " of " + std::to_string(db.num_states());
    } else {
        sub += "     " + std::to_string(n) + " states";
    }
    if (ps.mirror.any()) sub += "     mirrored " + mirror_name(ps.mirror);
    if (ps.deform_scale != 1.0) {
        char b[64];
        std::snprintf(b, sizeof b, "     displacements x %g", ps.deform_scale);
        sub += b;
    }
    font.draw(img, margin, margin + title_px + sub_px / 2 + font.ascent(sub_px), sub, sub_px, {60, 60, 60});
    if (seq)
        for (int i = 0; i < n; ++i) {
            const int si = ordered[i].index;
            const std::string cap = format_time(db.time(si), t_last, ps.units);
            font.draw(img, area_x + i * pw + pw / 2, area_y + area_h + sub_px + sub_px / 2, cap, sub_px, kText, HAlign::Center);
        }

    // ---- legend
    if (show_legend && has_fringe) {
        const int lx = W - legend_w - margin / 2;
        int y = area_y + unit;
        const DisplayUnit du = display_unit(q.dim, std::max(std::fabs(range.lo), std::fabs(range.hi)), ps.units);
        // quantity label, wrapped on words to the legend width
        std::vector<std::string> lines;
        {
            std::string cur, word;
            std::string text = q.label + " ";
            for (char c : text) {
                if (c != ' ') { word += c; continue; }
                const std::string trial = cur.empty() ? word : cur + " " + word;
                if (!cur.empty() && font.measure(trial, sub_px) > legend_w) { lines.push_back(cur); cur = word; }
                else cur = trial;
                word.clear();
            }
            if (!cur.empty()) lines.push_back(cur);
            if (!du.name.empty()) lines.push_back("(" + du.name + ")");
        }
        for (const auto& l : lines) {
            y += font.ascent(sub_px);
            font.draw(img, lx, y, l, sub_px, kText);
            y += font.descent(sub_px) + 2;
        }
        y += unit / 2;
        const int bar_w = unit * 3 / 2;
        const int bar_h = std::max(area_h / 2, ps.bands * 8);
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
        if (have_extreme) {
            const bool elem = q.where == Quantity::Where::Element;
            auto ext = [&](const char* what, double v, int id, int st) {
                std::string s = std::string(what) + " " + format_number(v * du.factor, step);
                y += font.ascent(label_px);
                font.draw(img, lx, y, s, label_px, kText);
                y += font.descent(label_px) + 2;
                const Family fam = elem ? element_ref(g, id).family : Family::Solid;
                std::string w = (elem ? (fam == Family::Solid ? std::string("elem") : std::string(family_name(fam))) + " " +
                                            std::to_string(db.element_id(id))
                                      : "node " + std::to_string(db.node_id(id)));
                if (seq) w += ", " + format_time(db.time(st), t_last, ps.units);
                y += font.ascent(label_px);
                font.draw(img, lx + unit / 2, y, w, label_px, {70, 70, 70});
                y += font.descent(label_px) + unit / 3;
            };
            ext("max", vmax, vmax_id, vmax_state);
            ext("min", vmin, vmin_id, vmin_state);
        }
    } else if (show_legend && is_material) {
        const int lx = W - legend_w - margin / 2;
        int y = area_y + unit;
        const int tx = lx + unit * 3 / 2, text_w = W - margin / 2 - tx;
        for (int m = 1; m <= g.num_materials; ++m) {
            img.fill_rect(lx, y, lx + unit, y + unit, material_color(m));
            img.rect_outline(lx, y, lx + unit, y + unit, kBlack);
            // the part name, wrapped on words to the legend column (long titles were cut off)
            std::vector<std::string> lines;
            std::string cur, word;
            for (char c : db.part_name(m) + " ") {
                if (c != ' ') { word += c; continue; }
                if (word.empty()) continue;
                const std::string trial = cur.empty() ? word : cur + " " + word;
                if (!cur.empty() && font.measure(trial, label_px) > text_w) { lines.push_back(cur); cur = word; }
                else cur = trial;
                word.clear();
            }
            if (!cur.empty()) lines.push_back(cur);
            const int line_h = font.ascent(label_px) + font.descent(label_px) + 2;
            int ty = y + unit - 3;
            for (const auto& l : lines) {
                font.draw(img, tx, ty, l, label_px, kText);
                ty += line_h;
            }
            y += std::max(unit * 3 / 2, unit + line_h * (static_cast<int>(lines.size()) - 1) + unit / 2);
        }
    }

    // ---- axis triad, bottom left
    if (ps.triad) {
        // in the legend column when there is one (it never covers the model), else bottom left
        const int len = unit * 2;
        const int ox = show_legend ? W - legend_w / 2 - margin / 2 : margin + len + unit / 2;
        const int oy = H - margin - len - caption;
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

    // ---- marks: a ring with four ticks at the projected node / element centroid, and a label
    if (spots) spots->clear();
    for (const PictureMark& m : ps.marks) {
        bool node = false;
        const int idx = find_marked(db, m, node);
        const std::string label = m.label.empty() ? m.what + " " + std::to_string(m.id) : m.label;
        for (int i = 0; i < n; ++i) {
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
    return img;
}

}  // namespace postimpact
