#include "postimpact/elements.h"

namespace postimpact {

namespace {

int family_count(const impact3d::PlotGeometry& g, Family f) {
    switch (f) {
        case Family::Solid: return g.num_hexes();
        case Family::ThickShell: return g.num_tshells();
        case Family::Beam: return g.num_beams();
        case Family::Shell: return g.num_shells();
    }
    return 0;
}

constexpr Family kOrder[] = {Family::Solid, Family::ThickShell, Family::Beam, Family::Shell};

bool flag(const std::vector<unsigned char>& v, int i) {
    return v.empty() || static_cast<std::size_t>(i) >= v.size() || v[static_cast<std::size_t>(i)] != 0;
}

}  // namespace

int num_elements(const impact3d::PlotGeometry& g) {
    return g.num_hexes() + g.num_tshells() + g.num_beams() + g.num_shells();
}

int family_offset(const impact3d::PlotGeometry& g, Family f) {
    int off = 0;
    for (Family k : kOrder) {
        if (k == f) return off;
        off += family_count(g, k);
    }
    return off;
}

ElementRef element_ref(const impact3d::PlotGeometry& g, int e) {
    for (Family k : kOrder) {
        const int n = family_count(g, k);
        if (e < n) return {k, e};
        e -= n;
    }
    return {Family::Shell, e};
}

const char* family_name(Family f) {
    switch (f) {
        case Family::Solid: return "solid";
        case Family::ThickShell: return "thick shell";
        case Family::Beam: return "beam";
        case Family::Shell: return "shell";
    }
    return "";
}

int element_user_id(const impact3d::PlotGeometry& g, int e) {
    const ElementRef r = element_ref(g, e);
    const std::vector<int>* ids = nullptr;
    switch (r.family) {
        case Family::Solid: ids = &g.hex_user_ids; break;
        case Family::ThickShell: ids = &g.tshell_user_ids; break;
        case Family::Beam: ids = &g.beam_user_ids; break;
        case Family::Shell: ids = &g.shell_user_ids; break;
    }
    return ids->empty() ? r.index + 1 : (*ids)[static_cast<std::size_t>(r.index)];
}

int element_material(const impact3d::PlotGeometry& g, int e) {
    const ElementRef r = element_ref(g, e);
    const std::size_t i = static_cast<std::size_t>(r.index);
    switch (r.family) {
        case Family::Solid: return g.hex_material[i];
        case Family::ThickShell: return g.tshell_material[i];
        case Family::Beam: return g.beam_material[i];
        case Family::Shell: return g.shell_material[i];
    }
    return 1;
}

const int* element_nodes(const impact3d::PlotGeometry& g, int e, int& count) {
    const ElementRef r = element_ref(g, e);
    const std::size_t i = static_cast<std::size_t>(r.index);
    switch (r.family) {
        case Family::Solid: count = 8; return &g.hex_nodes[8 * i];
        case Family::ThickShell: count = 8; return &g.tshell_nodes[8 * i];
        case Family::Beam: count = 2; return &g.beam_nodes[2 * i];
        case Family::Shell: count = 4; return &g.shell_nodes[4 * i];
    }
    count = 0;
    return nullptr;
}

bool element_alive(const impact3d::PlotState& s, const impact3d::PlotGeometry& g, int e) {
    const ElementRef r = element_ref(g, e);
    switch (r.family) {
        case Family::Solid: return flag(s.alive, r.index);
        case Family::ThickShell: return flag(s.tshell_alive, r.index);
        case Family::Beam: return flag(s.beam_alive, r.index);
        case Family::Shell: return flag(s.shell_alive, r.index);
    }
    return true;
}

}  // namespace postimpact
