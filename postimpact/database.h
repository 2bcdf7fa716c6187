// A d3plot family opened for post-processing: the reader, user id lookup and a state cache.
#pragma once

#include <map>
#include <string>
#include <unordered_map>

#include "common/plot_database.h"

namespace postimpact {

class Database {
public:
    explicit Database(const std::string& root);  // throws std::runtime_error
    const std::string& root() const { return root_; }
    const impact3d::PlotGeometry& geometry() const { return reader_.geometry(); }
    const impact3d::PlotLayout& layout() const { return reader_.layout(); }
    int num_states() const { return reader_.num_states(); }
    double time(int i) const { return reader_.time(i); }
    const impact3d::PlotState& state(int i);  // 0-based, cached

    int node_id(int index) const;      // user id of a 0-based node index
    // Elements of all families in the numbering of elements.h (solids first).  A user id that
    // several families use names the first of them (solids, thick shells, beams, shells).
    int element_id(int index) const;
    int node_index(int user_id) const;  // -1 if none
    int element_index(int user_id) const;
    int element_index(int user_id, int family) const;  // an elements.h Family; -1 if none
    std::string part_name(int material) const;  // 1-based material number

private:
    std::string root_;
    impact3d::PlotReader reader_;
    std::map<int, impact3d::PlotState> cache_;
    std::size_t cache_bytes_ = 0;
    std::unordered_map<int, int> node_lookup_, elem_lookup_;
};

}  // namespace postimpact
