// A plot database opened for post-processing: a d3plot family (common/plot_database) or a
// Mili database (common/mili_database, DYNA3D's own), chosen by the file's content; user id
// lookup and a state cache.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <unordered_map>

#include "common/mili_database.h"
#include "common/plot_database.h"

namespace postimpact {

class Database {
public:
    // root: a d3plot root file, or a Mili database: an A file (NAMEA), its base name NAME, or
    // the base name of a parallel run's processor files NAME000A, NAME001A, ... (merged by
    // label).  Throws std::runtime_error.
    explicit Database(const std::string& root);
    const std::string& root() const { return root_; }
    bool is_mili() const { return mili_ != nullptr; }
    const impact3d::MiliDatabase* mili() const { return mili_.get(); }
    const impact3d::PlotGeometry& geometry() const { return mili_ ? mili_->geometry() : reader_.geometry(); }
    const impact3d::PlotLayout& layout() const { return mili_ ? mili_->layout() : reader_.layout(); }
    int num_states() const { return mili_ ? mili_->num_states() : reader_.num_states(); }
    double time(int i) const { return mili_ ? mili_->time(i) : reader_.time(i); }
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
    std::unique_ptr<impact3d::MiliDatabase> mili_;
    std::map<int, impact3d::PlotState> cache_;
    std::size_t cache_bytes_ = 0;
    std::unordered_map<int, int> node_lookup_, elem_lookup_;
};

}  // namespace postimpact
