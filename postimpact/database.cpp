#include "postimpact/database.h"

#include "postimpact/elements.h"

namespace postimpact {


Database::Database(const std::string& root) : root_(root) {
    // a Mili database by its first bytes (the A file, NAMEA, or the processors' A files)
    if (!impact3d::MiliDatabase::a_files(root).empty()) {
        mili_ = std::make_unique<impact3d::MiliDatabase>();
        mili_->open(root);
    } else {
        reader_.open(root);
    }
    const auto& g = geometry();
    for (std::size_t i = 0; i < g.node_user_ids.size(); ++i) node_lookup_.emplace(g.node_user_ids[i], static_cast<int>(i));
    for (int e = 0; e < num_elements(g); ++e) elem_lookup_.emplace(element_user_id(g, e), e);  // first one kept
}

const impact3d::PlotState& Database::state(int i) {
    if (auto it = cache_.find(i); it != cache_.end()) return it->second;
    impact3d::PlotState s = mili_ ? mili_->state(i) : reader_.state(i);
    const std::size_t bytes = 8 * (s.coords.size() + s.vel.size() + s.acc.size() + s.stress.size() + s.eps.size() +
                                   s.temperature.size() + s.solid_vars.size() + s.tshell_vars.size() +
                                   s.beam_vars.size() + s.shell_vars.size());
    if (cache_bytes_ + bytes > (std::size_t{1} << 30)) {  // keep the cache under 1 GiB
        cache_.clear();
        cache_bytes_ = 0;
    }
    cache_bytes_ += bytes;
    return cache_.emplace(i, std::move(s)).first->second;
}

int Database::node_id(int index) const {
    const auto& g = geometry();
    return g.node_user_ids.empty() ? index + 1 : g.node_user_ids[index];
}

int Database::element_id(int index) const { return element_user_id(geometry(), index); }

int Database::node_index(int id) const {
    const auto& g = geometry();
    if (g.node_user_ids.empty()) return (id >= 1 && id <= g.num_nodes()) ? id - 1 : -1;
    auto it = node_lookup_.find(id);
    return it == node_lookup_.end() ? -1 : it->second;
}

int Database::element_index(int id) const {
    auto it = elem_lookup_.find(id);
    return it == elem_lookup_.end() ? -1 : it->second;
}

int Database::element_index(int id, int family) const {
    const auto& g = geometry();
    const int first = family_offset(g, static_cast<Family>(family));
    const int n = num_elements(g);
    for (int e = first; e < n && element_ref(g, e).family == static_cast<Family>(family); ++e)
        if (element_user_id(g, e) == id) return e;
    return -1;
}

std::string Database::part_name(int material) const {
    const auto& g = geometry();
    if (material >= 1 && material <= static_cast<int>(g.part_titles.size())) {
        std::string t = g.part_titles[material - 1];
        while (!t.empty() && t.back() == ' ') t.pop_back();
        if (!t.empty()) return t;
    }
    return "part " + std::to_string(material);
}

}  // namespace postimpact
