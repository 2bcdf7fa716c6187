// A small writer of Mili databases for the tests (and the fuzz seeds): it follows the format as
// common/mili_database.h describes it, independently of the reader.  It writes a PlotGeometry
// (solids, beams, shells) and a list of PlotStates the way DYNA3D lays them out:
//   classes  glob (mesh), mat, node, brick (hex), beam, shell, and a contact-segment class
//            "cseg" on the first shell faces (the reader must leave it out);
//   params   title, mesh dimensions, node and element labels (the beams' labels in two
//            parameters, one per connectivity block), part titles;
//   records  glob: ke pe te rbvx rbvy rbvz (result ordered, one object);
//            mat: matpe matke (object ordered);
//            node: nodpos (float) then nodvel (double) then nodacc (float), result ordered;
//            brick: stress eps sand, object ordered, in two ordinal blocks;
//            beam: two subrecords (first half, second half): axf sfs sft ms mt tor sand; with
//            Options::beam_points a third: es_1a (per point sx sy sz sxy syz szx eps, global
//            axes, as DYNA3D writes them) and svec, taken from the words after the states'
//            6 resultants per beam (per beam 7 x beam_points + 3 words);
//            shell: stress_mid eeff_mid stress_in eeff_in stress_out eeff_out bend shear normal
//            thick inteng es_3c (strains at 2 points: inner, outer) sand.
// Options: file version 2 (state maps in the A file) or 3 (in the T file), directory version
// 2 (int32 entries) or 3 (int64), either byte order, states per state file.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/plot_database.h"

namespace mili_test {

struct Options {
    int file_version = 2;       // 2 or 3
    int dir_version = 2;        // 2 (int32 directory entries) or 3 (int64)
    bool big_endian = false;
    int states_per_file = 2;
    int beam_points = 0;        // > 0: the beams' es_1a points and svec (see above)
};

class Writer {
public:
    explicit Writer(Options o) : o_(o) {
        const std::uint16_t one = 1;
        unsigned char c;
        std::memcpy(&c, &one, 1);
        swap_ = o_.big_endian != (c == 0);
    }

    // Writes BASE + "A", the state files BASE + "00", "01", ... and, for file version 3,
    // BASE + "T".  Shell records use the reader's 45-word layout (kShellWords).
    void write(const std::string& base, const impact3d::PlotGeometry& g, const std::vector<impact3d::PlotState>& states) {
        g_ = &g;
        dirs_.clear();
        define(g);
        // state files
        std::vector<std::string> files;
        std::vector<std::int32_t> smap_file;
        std::vector<std::int64_t> smap_offset;
        for (std::size_t k = 0; k < states.size(); ++k) {
            const std::size_t f = k / static_cast<std::size_t>(o_.states_per_file);
            if (files.size() <= f) files.emplace_back();
            std::string& out = files[f];
            smap_file.push_back(static_cast<std::int32_t>(f));
            smap_offset.push_back(static_cast<std::int64_t>(out.size()));
            f32(out, static_cast<float>(states[k].time));
            i32(out, 0);
            out += record(states[k]);
        }
        for (std::size_t f = 0; f < files.size(); ++f) {
            const std::string num = (f < 10 ? "0" : "") + std::to_string(f);
            save(base + num, files[f]);
        }
        // A file: header, directory data, strings, entries, state maps, footer
        std::string a = "mili";
        a += static_cast<char>(o_.file_version);
        a += static_cast<char>(o_.dir_version);
        a += static_cast<char>(o_.big_endian ? 1 : 2);
        a += static_cast<char>(1);  // precision: single
        a += static_cast<char>(2);  // state-file suffix length
        a += static_cast<char>(1);  // partition by state count
        a.append(6, '\0');
        std::vector<std::int64_t> offsets;
        for (const Dir& d : dirs_) {
            offsets.push_back(d.data.empty() ? 0 : static_cast<std::int64_t>(a.size()));
            a += d.data;
        }
        std::string strings;
        for (const Dir& d : dirs_)
            for (const std::string& s : d.s) strings += s + '\0';
        while (strings.size() % 4) strings += '\0';
        a += strings;
        const int w = o_.dir_version <= 2 ? 4 : 8;
        for (std::size_t k = 0; k < dirs_.size(); ++k) {
            const Dir& d = dirs_[k];
            for (std::int64_t x : {d.type, d.m1, d.m2, static_cast<std::int64_t>(d.s.size()), offsets[k],
                                   static_cast<std::int64_t>(d.data.size())}) {
                if (w == 4) i32(a, static_cast<std::int32_t>(x));
                else i64(a, x);
            }
        }
        std::string smaps;
        for (std::size_t k = 0; k < states.size(); ++k) {
            i32(smaps, smap_file[k]);
            i64(smaps, smap_offset[k]);
            f32(smaps, static_cast<float>(states[k].time));
            i32(smaps, 0);
        }
        if (o_.file_version >= 3) save(base + "T", smaps + "~");
        else a += smaps;
        i32(a, static_cast<std::int32_t>(strings.size()));
        i32(a, 1);
        i32(a, static_cast<std::int32_t>(dirs_.size()));
        i32(a, static_cast<std::int32_t>(states.size()));
        save(base + "A", a);
    }

    static constexpr int kShellWords = 45;

private:
    struct Dir {
        std::int64_t type = 0, m1 = 0, m2 = 0;
        std::vector<std::string> s;
        std::string data;
    };
    struct Var {
        int agg = 0, type = 2;
        std::string name, title;
        std::vector<int> dims;
        std::vector<std::string> comps;
    };
    // One subrecord: class, organization, 1-based (first, last) blocks, top variables, and per
    // top variable the atom types and a value function (state, 0-based ordinal, atom).
    struct Srec {
        std::string name, cls;
        int org = 1;
        bool mesh = false;
        std::vector<std::pair<int, int>> blocks;
        std::vector<std::string> tops;
        std::vector<std::vector<int>> types;
        std::function<double(const impact3d::PlotState&, int, int, int)> value;  // (state, ordinal, top, atom)
    };

    template <class T> void put(std::string& b, T v) {
        char t[sizeof(T)];
        std::memcpy(t, &v, sizeof(T));
        if (swap_) std::reverse(t, t + sizeof(T));
        b.append(t, sizeof(T));
    }
    void i32(std::string& b, std::int32_t v) { put(b, v); }
    void i64(std::string& b, std::int64_t v) { put(b, v); }
    void f32(std::string& b, float v) { put(b, v); }
    void f64(std::string& b, double v) { put(b, v); }
    static void save(const std::string& path, const std::string& bytes) {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (!f) throw std::runtime_error("mili_test::Writer: cannot write " + path);
    }

    void dir(int type, std::int64_t m1, std::int64_t m2, std::vector<std::string> s, std::string data) {
        dirs_.push_back({type, m1, m2, std::move(s), std::move(data)});
    }
    void param_string(int type, const std::string& name, const std::string& value) {
        std::string d = value + '\0';
        while (d.size() % 8) d += '\0';
        dir(type, 1, 0, {name}, d);
    }
    void param_int(int type, const std::string& name, std::int32_t value) {
        std::string d;
        i32(d, value);
        dir(type, 5, 0, {name}, d);
    }
    void param_ints(const std::string& name, const std::vector<int>& v) {
        std::string d;
        i32(d, 1);
        i32(d, static_cast<std::int32_t>(v.size()));
        for (int x : v) i32(d, x);
        dir(9, 5, 2, {name}, d);
    }
    void class_def(const std::string& name, const std::string& title, int superclass) { dir(7, 0, superclass, {name, title}, ""); }
    void idents(const std::string& name, int superclass, int first, int last) {
        std::string d;
        i32(d, superclass);
        i32(d, first);
        i32(d, last);
        dir(2, 0, 0, {name}, d);
    }
    // connectivity of elements first..last (1-based) of a class, nodes per element nn
    void conns(const std::string& cls, int superclass, int first, int last, int nn, const std::vector<int>& nodes,
               int nodes_stride, const std::vector<int>& mat) {
        std::string d;
        i32(d, superclass);
        i32(d, 1);
        i32(d, first);
        i32(d, last);
        for (int e = first - 1; e < last; ++e) {
            for (int j = 0; j < nn; ++j) {
                const int n = j < nodes_stride ? nodes[static_cast<std::size_t>(e * nodes_stride + j)] : nodes[static_cast<std::size_t>(e * nodes_stride)];
                i32(d, n + 1);
            }
            i32(d, mat[static_cast<std::size_t>(e)]);
            i32(d, mat[static_cast<std::size_t>(e)]);  // part = material
        }
        dir(1, 0, last - first + 1, {cls}, d);
    }

    void define(const impact3d::PlotGeometry& g) {
        const int nn = g.num_nodes(), nh = g.num_hexes(), nb = g.num_beams(), ns = g.num_shells();
        const int nm = g.num_materials;
        param_string(5, "lib version", "test writer");
        param_string(6, "title", g.title);
        param_int(5, "mesh dimensions", 3);
        class_def("glob", "Global", 11);
        idents("glob", 11, 1, 1);
        class_def("mat", "Material", 10);
        idents("mat", 10, 1, nm);
        class_def("node", "Node", 1);
        {
            std::string d;
            i32(d, 1);
            i32(d, nn);
            for (double x : g.x0) f32(d, static_cast<float>(x));
            dir(0, 1, nn, {"node"}, d);
        }
        param_ints("Node Labels[/Mesh-0/Sname-node/Scls-M_NODE/Mat--1/]", labels(g.node_user_ids, nn));
        if (nh > 0) {
            class_def("brick", "Bricks", 9);
            conns("brick", 9, 1, nh, 8, g.hex_nodes, 8, g.hex_material);
            param_ints("Element Labels[/Mesh-0/Sname-brick/Scls-M_HEX/Mat-0/]", labels(g.hex_user_ids, nh));
        }
        if (nb > 0) {  // two connectivity blocks, each with its labels (the third node: orientation)
            class_def("beam", "Beams", 3);
            const std::vector<int> lab = labels(g.beam_user_ids, nb);
            const int half = (nb + 1) / 2;
            conns("beam", 3, 1, half, 3, g.beam_nodes, 2, g.beam_material);
            param_ints("Element Labels[/Mesh-0/Sname-beam/Scls-M_BEAM/Mat-0/]", {lab.begin(), lab.begin() + half});
            if (half < nb) {
                conns("beam", 3, half + 1, nb, 3, g.beam_nodes, 2, g.beam_material);
                param_ints("Element Labels[/Mesh-0/Sname-beam/Scls-M_BEAM/Mat-1/]", {lab.begin() + half, lab.end()});
            }
        }
        if (ns > 0) {
            class_def("shell", "Shells", 5);
            conns("shell", 5, 1, ns, 4, g.shell_nodes, 4, g.shell_material);
            param_ints("Element Labels[/Mesh-0/Sname-shell/Scls-M_QUAD/Mat-0/]", labels(g.shell_user_ids, ns));
            class_def("cseg", "Contact Segment", 5);  // contact segments on the first shell: not drawn
            conns("cseg", 5, 1, 1, 4, g.shell_nodes, 4, g.shell_material);
        }
        for (int m = 1; m <= nm; ++m)
            param_string(9, "part_title_" + std::to_string(m),
                         m <= static_cast<int>(g.part_titles.size()) ? g.part_titles[static_cast<std::size_t>(m - 1)] : "");
        variables();
        subrecords(g);
    }

    static std::vector<int> labels(const std::vector<int>& ids, int n) {
        if (!ids.empty()) return ids;
        std::vector<int> v(static_cast<std::size_t>(n));
        for (int k = 0; k < n; ++k) v[static_cast<std::size_t>(k)] = k + 1;
        return v;
    }

    void variables() {
        std::vector<Var> v;
        auto scalar = [&](const std::string& n, int type = 2) { v.push_back({0, type, n, n + " title", {}, {}}); };
        auto vec = [&](const std::string& n, std::vector<std::string> c) { v.push_back({1, 2, n, n + " title", {}, std::move(c)}); };
        for (const char* n : {"ke", "pe", "te", "rbvx", "rbvy", "rbvz"}) scalar(n);
        vec("nodpos", {"ux", "uy", "uz"});   // components defined inline right after
        for (const char* n : {"ux", "uy", "uz"}) scalar(n);
        for (const char* n : {"vx", "vy", "vz"}) scalar(n, 4);  // double precision
        vec("nodvel", {"vx", "vy", "vz"});
        vec("nodacc", {"ax", "ay", "az"});
        for (const char* n : {"ax", "ay", "az"}) scalar(n);
        for (const char* n : {"sx", "sy", "sz", "sxy", "syz", "szx"}) scalar(n);
        vec("stress", {"sx", "sy", "sz", "sxy", "syz", "szx"});
        for (const char* n : {"eps", "sand", "axf", "sfs", "sft", "ms", "mt", "tor"}) scalar(n);
        for (const char* n : {"stress_mid", "stress_in", "stress_out"}) vec(n, {"sx", "sy", "sz", "sxy", "syz", "szx"});
        for (const char* n : {"eeff_mid", "eeff_in", "eeff_out"}) scalar(n);
        vec("bend", {"mxx", "myy", "mxy"});
        for (const char* n : {"mxx", "myy", "mxy"}) scalar(n);
        vec("shear", {"qxx", "qyy"});
        for (const char* n : {"qxx", "qyy"}) scalar(n);
        vec("normal", {"nxx", "nyy", "nxy"});
        for (const char* n : {"nxx", "nyy", "nxy"}) scalar(n);
        for (const char* n : {"thick", "inteng", "ex", "ey", "ez", "exy", "eyz", "ezx", "matpe", "matke"}) scalar(n);
        v.push_back({3, 2, "es_3c", "Element Set 3c", {2}, {"ex", "ey", "ez", "exy", "eyz", "ezx"}});
        if (o_.beam_points > 0) {
            v.push_back({3, 2, "es_1a", "Element Set 1a", {o_.beam_points}, {"sx", "sy", "sz", "sxy", "syz", "szx", "eps"}});
            for (const char* n : {"svec_x", "svec_y", "svec_z"}) scalar(n);
            vec("svec", {"svec_x", "svec_y", "svec_z"});
        }
        std::string ints, strs;
        for (const Var& x : v) {
            i32(ints, x.agg);
            i32(ints, x.type);
            strs += x.name + '\0' + x.title + '\0';
            if (x.agg >= 2) {
                i32(ints, static_cast<std::int32_t>(x.dims.size()));
                for (int d : x.dims) i32(ints, d);
            }
            if (x.agg == 1 || x.agg == 3) {
                i32(ints, static_cast<std::int32_t>(x.comps.size()));
                for (const std::string& c : x.comps) strs += c + '\0';
            }
        }
        while (strs.size() % 4) strs += '\0';
        std::string d;
        i32(d, static_cast<std::int32_t>(ints.size() / 4 + 2));
        i32(d, static_cast<std::int32_t>(strs.size()));
        dir(3, 0, 0, {}, d + ints + strs);
    }

    void subrecords(const impact3d::PlotGeometry& g) {
        using S = impact3d::PlotState;
        const int nn = g.num_nodes(), nh = g.num_hexes(), nb = g.num_beams(), ns = g.num_shells();
        auto at = [](const std::vector<double>& v, std::size_t i) { return i < v.size() ? v[i] : 0.0; };
        auto alive = [](const std::vector<unsigned char>& v, int e) {
            return e < static_cast<int>(v.size()) && v[static_cast<std::size_t>(e)] == 0 ? 0.0 : 1.0;
        };
        srecs_.clear();
        srecs_.push_back({"glob", "glob", 0, true, {{1, 1}}, {"ke", "pe", "te", "rbvx", "rbvy", "rbvz"},
                          {{2}, {2}, {2}, {2}, {2}, {2}}, [](const S& s, int, int t, int) {
                              const double v[6] = {s.kinetic_energy, s.internal_energy, s.total_energy,
                                                   s.velocity[0], s.velocity[1], s.velocity[2]};
                              return v[t];
                          }});
        if (g.num_materials > 0)
            srecs_.push_back({"mat", "mat", 1, false, {{1, g.num_materials}}, {"matpe", "matke"}, {{2}, {2}},
                              [at](const S& s, int m, int t, int) {
                                  return at(t == 0 ? s.mat_internal_energy : s.mat_kinetic_energy, static_cast<std::size_t>(m));
                              }});
        srecs_.push_back({"node", "node", 0, false, {{1, nn}}, {"nodpos", "nodvel", "nodacc"},
                          {{2, 2, 2}, {4, 4, 4}, {2, 2, 2}}, [at](const S& s, int n, int t, int j) {
                              const std::size_t i = 3 * static_cast<std::size_t>(n) + static_cast<std::size_t>(j);
                              return at(t == 0 ? s.coords : t == 1 ? s.vel : s.acc, i);
                          }});
        if (nh > 0) {
            const int half = (nh + 1) / 2;
            std::vector<std::pair<int, int>> blocks = {{1, half}};
            if (half < nh) blocks.emplace_back(half + 1, nh);
            srecs_.push_back({"1hex", "brick", 1, false, blocks, {"stress", "eps", "sand"}, {{2, 2, 2, 2, 2, 2}, {2}, {2}},
                              [at, alive](const S& s, int e, int t, int j) {
                                  if (t == 0) return at(s.stress, 6 * static_cast<std::size_t>(e) + static_cast<std::size_t>(j));
                                  return t == 1 ? at(s.eps, static_cast<std::size_t>(e)) : alive(s.alive, e);
                              }});
        }
        if (nb > 0) {
            const int half = (nb + 1) / 2;
            for (int part = 0; part < 2; ++part) {
                const int first = part == 0 ? 1 : half + 1, last = part == 0 ? half : nb;
                if (first > last) continue;
                srecs_.push_back({std::to_string(part + 1) + "beam", "beam", 1, false, {{first, last}},
                                  {"axf", "sfs", "sft", "ms", "mt", "tor", "sand"}, {{2}, {2}, {2}, {2}, {2}, {2}, {2}},
                                  [at, alive](const S& s, int e, int t, int) {
                                      return t < 6 ? at(s.beam_vars, 6 * static_cast<std::size_t>(e) + static_cast<std::size_t>(t))
                                                   : alive(s.beam_alive, e);
                                  }});
            }
            if (o_.beam_points > 0) {
                const int np = o_.beam_points;
                const std::size_t per = 7 * static_cast<std::size_t>(np) + 3;
                srecs_.push_back({"3beam", "beam", 1, false, {{1, nb}}, {"es_1a", "svec"},
                                  {std::vector<int>(7 * static_cast<std::size_t>(np), 2), {2, 2, 2}},
                                  [at, nb, np, per](const S& s, int e, int t, int j) {
                                      const std::size_t b = 6 * static_cast<std::size_t>(nb) + per * static_cast<std::size_t>(e);
                                      return at(s.beam_vars, b + static_cast<std::size_t>(t == 0 ? j : 7 * np + j));
                                  }});
            }
        }
        if (ns > 0) {
            const std::vector<int> six(6, 2), three(3, 2), two(2, 2), twelve(12, 2);
            srecs_.push_back({"1shell", "shell", 1, false, {{1, ns}},
                              {"stress_mid", "eeff_mid", "stress_in", "eeff_in", "stress_out", "eeff_out", "bend", "shear",
                               "normal", "thick", "inteng", "es_3c", "sand"},
                              {six, {2}, six, {2}, six, {2}, three, two, three, {2}, {2}, twelve, {2}},
                              [at, alive](const S& s, int e, int t, int j) {
                                  const std::size_t r = kShellWords * static_cast<std::size_t>(e);
                                  static const int base[12] = {0, 6, 7, 13, 14, 20, 21, 24, 26, 29, 32, 33};
                                  if (t == 12) return alive(s.shell_alive, e);
                                  return at(s.shell_vars, r + static_cast<std::size_t>(base[t] + j));
                              }});
        }
        std::string ints, strs;
        std::int64_t size = 0;
        for (const Srec& r : srecs_) {
            i32(ints, r.org);
            i32(ints, static_cast<std::int32_t>(r.tops.size()));
            i32(ints, r.mesh ? 0 : static_cast<std::int32_t>(r.blocks.size()));
            if (!r.mesh)
                for (const auto& [a, b] : r.blocks) {
                    i32(ints, a);
                    i32(ints, b);
                }
            strs += r.name + '\0' + r.cls + '\0';
            for (const std::string& t : r.tops) strs += t + '\0';
            std::int64_t objects = 0;
            for (const auto& [a, b] : r.blocks) objects += b - a + 1;
            for (const auto& ty : r.types)
                for (int x : ty) size += objects * (x == 4 ? 8 : 4);
        }
        while (strs.size() % 4) strs += '\0';
        std::string d;
        i32(d, 0);
        i32(d, 0);
        i32(d, static_cast<std::int32_t>(size));
        i32(d, static_cast<std::int32_t>(srecs_.size()));
        dir(4, static_cast<std::int64_t>(ints.size() / 4 + 4), static_cast<std::int64_t>(strs.size()), {}, d + ints + strs);
    }

    std::string record(const impact3d::PlotState& s) {
        std::string out;
        auto val = [&](int type, double v) {
            if (type == 4) f64(out, v);
            else f32(out, static_cast<float>(v));
        };
        for (const Srec& r : srecs_) {
            std::vector<int> ords;
            for (const auto& [a, b] : r.blocks)
                for (int o = a; o <= b; ++o) ords.push_back(o - 1);
            if (r.org == 1) {
                for (int o : ords)
                    for (std::size_t t = 0; t < r.tops.size(); ++t)
                        for (std::size_t j = 0; j < r.types[t].size(); ++j)
                            val(r.types[t][j], r.value(s, o, static_cast<int>(t), static_cast<int>(j)));
            } else {
                for (std::size_t t = 0; t < r.tops.size(); ++t)
                    for (int o : ords)
                        for (std::size_t j = 0; j < r.types[t].size(); ++j)
                            val(r.types[t][j], r.value(s, o, static_cast<int>(t), static_cast<int>(j)));
            }
        }
        return out;
    }

    Options o_;
    bool swap_ = false;
    const impact3d::PlotGeometry* g_ = nullptr;
    std::vector<Dir> dirs_;
    std::vector<Srec> srecs_;
};

// A small model of every family the writer writes: 2 solids (material 1) in a 2x1x1 box of
// 12 nodes, 3 beams along its bottom edges (material 2), 2 shells on its top face (material
// 3); user labels 101.., 11.., 21.., 31..; `n` states whose values are exact in single
// precision (velocities, written in double precision, are not), solid 12 deleted from state 2.
inline void sample_model(impact3d::PlotGeometry& g, std::vector<impact3d::PlotState>& states, int n) {
    g = impact3d::PlotGeometry{};
    g.title = "mili test model";
    g.num_materials = 3;
    g.part_titles = {"block", "rods", "skin"};
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i) {
                g.x0.insert(g.x0.end(), {0.5 * i, 0.25 * j, 0.125 * k});
                g.node_user_ids.push_back(101 + static_cast<int>(g.node_user_ids.size()));
            }
    auto node = [](int i, int j, int k) { return i + 3 * (j + 2 * k); };
    for (int e = 0; e < 2; ++e) {
        g.hex_nodes.insert(g.hex_nodes.end(), {node(e, 0, 0), node(e + 1, 0, 0), node(e + 1, 1, 0), node(e, 1, 0),
                                               node(e, 0, 1), node(e + 1, 0, 1), node(e + 1, 1, 1), node(e, 1, 1)});
        g.hex_material.push_back(1);
        g.hex_user_ids.push_back(11 + e);
        g.shell_nodes.insert(g.shell_nodes.end(), {node(e, 0, 1), node(e + 1, 0, 1), node(e + 1, 1, 1), node(e, 1, 1)});
        g.shell_material.push_back(3);
        g.shell_user_ids.push_back(31 + e);
    }
    g.beam_nodes = {node(0, 0, 0), node(1, 0, 0), node(1, 0, 0), node(2, 0, 0), node(0, 1, 0), node(1, 1, 0)};
    g.beam_material = {2, 2, 2};
    g.beam_user_ids = {21, 22, 23};
    states.clear();
    for (int k = 0; k < n; ++k) {
        impact3d::PlotState s;
        const double f = 0.25 * k;
        s.time = 0.5 * k;
        s.kinetic_energy = 10 + f;
        s.internal_energy = 20 + f;
        s.total_energy = 30 + 2 * f;
        s.velocity = {1 + f, 2 + f, 3 + f};
        s.mat_internal_energy = {1 + f, 2 + f, 3 + f};
        s.mat_kinetic_energy = {4 + f, 5 + f, 6 + f};
        for (std::size_t i = 0; i < g.x0.size(); ++i) {
            s.coords.push_back(g.x0[i] + 0.0625 * k * static_cast<double>(i % 5));
            s.vel.push_back(0.1 * k + static_cast<double>(i) / 3.0);
            s.acc.push_back(-8.0 * k + static_cast<double>(i));
        }
        for (int e = 0; e < 2; ++e) {
            for (int j = 0; j < 6; ++j) s.stress.push_back(100.0 * k + 10 * e + j - 2.5);
            s.eps.push_back(0.125 * k * (e + 1));
        }
        s.alive = {1, static_cast<unsigned char>(k >= 2 ? 0 : 1)};
        for (int b = 0; b < 3; ++b)
            for (int j = 0; j < 6; ++j) s.beam_vars.push_back(1000.0 * k - 50 * b + j);
        s.beam_alive = {1, 1, 1};
        for (int e = 0; e < 2; ++e)
            for (int j = 0; j < Writer::kShellWords; ++j)
                s.shell_vars.push_back(j == 30 || j == 31 ? 0.0 : 0.5 * k + 3 * e + 0.25 * j);
        s.shell_alive = {1, 1};
        states.push_back(std::move(s));
    }
}

}  // namespace mili_test
