// Mili database reader (see mili_database.h for the format).
#include "common/mili_database.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace impact3d {

namespace {

constexpr std::int64_t kLimit = std::int64_t{1} << 40;   // sizes beyond this are corrupt
constexpr int kMaxNesting = 8;                           // variables inside variables

[[noreturn]] void fail(const std::string& file, const std::string& what) {
    throw std::runtime_error("mili database " + file + ": " + what);
}

[[noreturn]] void fail_at(const std::string& file, std::int64_t offset, const std::string& what,
                          std::int64_t need, std::int64_t have) {
    std::ostringstream os;
    os << "mili database " << file << ": truncated or corrupt at byte offset " << offset << ": expected "
       << what;
    if (need >= 0) os << " (" << need << " bytes)";
    os << ", but the file has " << have << " bytes";
    throw std::runtime_error(os.str());
}

std::int64_t mul(std::int64_t a, std::int64_t b, const std::string& file, const char* what) {
    std::int64_t r;
    if (a < 0 || b < 0 || __builtin_mul_overflow(a, b, &r) || r > kLimit)
        fail(file, std::string("implausible size of ") + what);
    return r;
}
std::int64_t add(std::int64_t a, std::int64_t b, const std::string& file, const char* what) {
    std::int64_t r;
    if (a < 0 || b < 0 || __builtin_add_overflow(a, b, &r) || r > kLimit)
        fail(file, std::string("implausible size of ") + what);
    return r;
}

std::int64_t file_size(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec) || ec) return -1;
    const auto s = std::filesystem::file_size(path, ec);
    return ec ? -1 : static_cast<std::int64_t>(s);
}

std::vector<char> read_file(const std::string& path) {
    const std::int64_t size = file_size(path);
    if (size < 0) fail(path, "cannot open: no such regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
    std::vector<char> d(static_cast<std::size_t>(size));
    if (size > 0 && !in.read(d.data(), size)) fail(path, "read error");
    return d;
}

// Bounds-checked, byte-order aware loads from a file held in memory.
class View {
public:
    View(const std::vector<char>& d, std::string file, bool swap) : d_(d), file_(std::move(file)), swap_(swap) {}
    std::int64_t size() const { return static_cast<std::int64_t>(d_.size()); }
    void need(std::int64_t off, std::int64_t n, const std::string& what) const {
        if (off < 0 || n < 0 || off > size() || n > size() - off) fail_at(file_, off, what, n, size());
    }
    std::int32_t i32(std::int64_t off, const char* what) const { std::int32_t v; load(off, &v, 4, what); return v; }
    std::int64_t i64(std::int64_t off, const char* what) const { std::int64_t v; load(off, &v, 8, what); return v; }
    float f32(std::int64_t off, const char* what) const { float v; load(off, &v, 4, what); return v; }
    double f64(std::int64_t off, const char* what) const { double v; load(off, &v, 8, what); return v; }
    std::int64_t word(std::int64_t off, int w, const char* what) const { return w == 8 ? i64(off, what) : i32(off, what); }
    const std::string& file() const { return file_; }

private:
    void load(std::int64_t off, void* dst, int n, const char* what) const {
        need(off, n, what);
        char t[8];
        std::memcpy(t, d_.data() + off, static_cast<std::size_t>(n));
        if (swap_) std::reverse(t, t + n);
        std::memcpy(dst, t, static_cast<std::size_t>(n));
    }
    const std::vector<char>& d_;
    std::string file_;
    bool swap_;
};

bool host_big_endian() {
    const std::uint16_t x = 1;
    unsigned char c;
    std::memcpy(&c, &x, 1);
    return c == 0;
}

int type_bytes(int t) {
    switch (t) {
        case kMiliFloat: case kMiliFloat4: case kMiliInt: case kMiliInt4: return 4;
        case kMiliFloat8: case kMiliInt8: return 8;
        default: return 0;
    }
}

// NUL-terminated strings one after another in [off, off + n).
std::vector<std::string> split_strings(const std::vector<char>& d, std::int64_t off, std::int64_t n) {
    std::vector<std::string> out;
    std::int64_t k = off;
    const std::int64_t end = off + n;
    while (k < end) {
        std::int64_t e = k;
        while (e < end && d[static_cast<std::size_t>(e)] != '\0') ++e;
        out.emplace_back(d.data() + k, d.data() + e);
        k = e + 1;
    }
    return out;
}

// "Sname-brick/" -> "brick"
std::string class_in_label_name(const std::string& s) {
    const auto p = s.find("Sname-");
    if (p == std::string::npos) return "";
    const auto e = s.find('/', p);
    return s.substr(p + 6, e == std::string::npos ? std::string::npos : e - p - 6);
}

bool starts_with(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// An ordinal block first..last (from 1; empty when last = first - 1) of `what`.
void check_block(const std::string& file, std::int64_t first, std::int64_t last, const std::string& what) {
    if (first < 1 || last < first - 1 || last > (std::int64_t{1} << 31) - 2)
        fail(file, what + ": ordinal block " + std::to_string(first) + ".." + std::to_string(last));
}

// Ordinals up to `last` of class ci stay within the objects the file backs with data.
void check_backed(const std::string& file, const std::vector<std::int64_t>& backed, int ci, std::int64_t last,
                  const std::string& what) {
    if (last > backed[static_cast<std::size_t>(ci)])
        fail(file, what + ": ordinal " + std::to_string(last) + " beyond the " +
                       std::to_string(backed[static_cast<std::size_t>(ci)]) + " objects with data");
}

void grow(MiliClass& c, std::int64_t n) { c.count = std::max(c.count, n); }

}  // namespace

int mili_nodes_per_element(int sc) {
    static const int n[] = {0, 0, 2, 3, 3, 4, 4, 5, 6, 8, 0, 0, 0, 1, 10, 1};
    return sc >= 0 && sc < 16 ? n[sc] : 0;
}

bool MiliReader::is_mili_file(const std::string& path) {
    // "mili", then the file version, directory version (1..3) and endian flag (1, 2) as bytes:
    // a d3plot whose title starts with "mili" has text there
    std::ifstream in(path, std::ios::binary);
    char m[7] = {};
    return in && in.read(m, 7) && std::memcmp(m, "mili", 4) == 0 && m[4] >= 1 && m[4] <= 3 && m[5] >= 1 &&
           m[5] <= 3 && (m[6] == 1 || m[6] == 2);
}

int MiliReader::find_class(const std::string& name) const {
    for (std::size_t c = 0; c < classes_.size(); ++c)
        if (classes_[c].name == name) return static_cast<int>(c);
    return -1;
}

int MiliReader::find_variable(const std::string& name) const {
    for (std::size_t v = vars_.size(); v-- > 0;)  // a later definition wins
        if (vars_[v].name == name) return static_cast<int>(v);
    return -1;
}

std::string MiliReader::param_string(const std::string& name) const {
    auto it = params_.find(name);
    if (it == params_.end() || it->second.type != kMiliString || it->second.array) return "";
    const Param& p = it->second;
    std::string s(a_.data() + p.offset, a_.data() + p.offset + p.length);
    if (auto z = s.find('\0'); z != std::string::npos) s.resize(z);
    return s;
}

std::int64_t MiliReader::param_int(const std::string& name, std::int64_t dflt) const {
    auto it = params_.find(name);
    if (it == params_.end() || it->second.array) return dflt;
    const Param& p = it->second;
    const View v(a_, a_file_, big_endian_ != host_big_endian());
    if ((p.type == kMiliInt || p.type == kMiliInt4) && p.length >= 4) return v.i32(p.offset, "integer parameter");
    if (p.type == kMiliInt8 && p.length >= 8) return v.i64(p.offset, "integer parameter");
    return dflt;
}

std::vector<std::string> MiliReader::state_files() const {
    std::vector<std::string> out;
    for (const auto& m : smaps_) {
        std::string num = std::to_string(m.file);
        if (static_cast<int>(num.size()) < suffix_length_) num.insert(0, suffix_length_ - num.size(), '0');
        const std::string name = base_ + num;
        if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
    }
    return out;
}

void MiliReader::open(const std::string& path) {
    *this = MiliReader();
    read_header(path);
    const std::vector<Dir> dirs = read_directory();
    read_parameters(dirs);
    read_classes(dirs);
    read_labels(dirs);
    read_variables(dirs);
    read_record_format(dirs);
    check_state_maps();
    build_geometry();
}

// The A file: its 16-byte header (versions, byte order, state-file suffix length).
void MiliReader::read_header(const std::string& path) {
    a_file_ = path;
    if (path.empty() || path.back() != 'A') {
        if (file_size(path + "A") >= 0) a_file_ = path + "A";
    }
    if (a_file_.empty() || a_file_.back() != 'A')
        fail(path, "a Mili database is named by its A file (NAMEA)");
    base_ = a_file_.substr(0, a_file_.size() - 1);
    a_ = read_file(a_file_);
    const std::string& F = a_file_;
    const std::int64_t size = static_cast<std::int64_t>(a_.size());
    if (size < 32) fail_at(F, 0, "the 16-byte header and the 16-byte footer", 32, size);
    if (std::memcmp(a_.data(), "mili", 4) != 0) fail(F, "not a Mili A file: the first 4 bytes are not \"mili\"");
    const auto byte = [&](int k) { return static_cast<int>(static_cast<unsigned char>(a_[static_cast<std::size_t>(k)])); };
    file_version_ = byte(4);
    dir_version_ = byte(5);
    const int endian = byte(6);
    suffix_length_ = byte(8);
    if (file_version_ < 1 || file_version_ > 3)
        fail(F, "file version " + std::to_string(file_version_) + " at byte 4 (1 to 3 are read)");
    if (dir_version_ < 1 || dir_version_ > 3)
        fail(F, "directory version " + std::to_string(dir_version_) + " at byte 5 (1 to 3 are read)");
    if (endian != 1 && endian != 2)
        fail(F, "endian flag " + std::to_string(endian) + " at byte 6 (1 big, 2 little)");
    if (suffix_length_ < 1 || suffix_length_ > 9)
        fail(F, "state-file suffix length " + std::to_string(suffix_length_) + " at byte 8 (1 to 9)");
    big_endian_ = endian == 1;
}

// From the end of the A file backwards: the footer, the state maps (or the T file), the
// directory entries and the string table that names them.
std::vector<MiliReader::Dir> MiliReader::read_directory() {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    const std::int64_t size = static_cast<std::int64_t>(a_.size());
    const std::int64_t string_bytes = v.i32(size - 16, "footer: string-table bytes");
    const std::int64_t num_dirs = v.i32(size - 8, "footer: directory entries");
    const std::int64_t footer_smaps = v.i32(size - 4, "footer: state maps");
    if (string_bytes < 0 || num_dirs < 0 || footer_smaps < 0)
        fail(F, "negative count in the footer (last 16 bytes)");
    std::int64_t end = size - 16;
    const std::string t_file = base_ + "T";
    const bool use_t = file_version_ >= 3 && file_size(t_file) >= 0;
    auto read_smap = [&](const View& w, std::int64_t off) {
        StateMap m;
        m.file = w.i32(off, "state map: file number");
        m.offset = w.i64(off + 4, "state map: offset");
        m.time = w.f32(off + 12, "state map: time");
        m.id = w.i32(off + 16, "state map: record id");
        return m;
    };
    if (use_t) {
        const std::vector<char> t = read_file(t_file);
        const View tv(t, t_file, big_endian_ != host_big_endian());
        const std::int64_t n = static_cast<std::int64_t>(t.size()) / 20;
        for (std::int64_t k = 0; k < n; ++k) smaps_.push_back(read_smap(tv, 20 * k));
    } else {
        const std::int64_t bytes = mul(footer_smaps, 20, F, "the state maps");
        if (bytes > end - 16) fail_at(F, end - bytes, "the state maps the footer counts", bytes, size);
        end -= bytes;
        for (std::int64_t k = 0; k < footer_smaps; ++k) smaps_.push_back(read_smap(v, end + 20 * k));
    }
    const int w = dir_version_ <= 2 ? 4 : 8;
    const std::int64_t dir_bytes = mul(num_dirs, 6 * w, F, "the directory entries");
    if (dir_bytes > end - 16) fail_at(F, end - dir_bytes, "the directory entries the footer counts", dir_bytes, size);
    const std::int64_t dirs_at = end - dir_bytes;
    if (string_bytes > dirs_at - 16) fail_at(F, dirs_at - string_bytes, "the string table", string_bytes, size);
    const std::int64_t strings_at = dirs_at - string_bytes;
    const std::vector<std::string> strings = split_strings(a_, strings_at, string_bytes);

    std::vector<Dir> dirs(static_cast<std::size_t>(num_dirs));
    std::size_t next_string = 0;
    for (std::int64_t k = 0; k < num_dirs; ++k) {
        Dir& d = dirs[static_cast<std::size_t>(k)];
        const std::int64_t at = dirs_at + k * 6 * w;
        d.type = v.word(at, w, "directory entry");
        d.m1 = v.word(at + w, w, "directory entry");
        d.m2 = v.word(at + 2 * w, w, "directory entry");
        d.nstr = v.word(at + 3 * w, w, "directory entry");
        d.offset = v.word(at + 4 * w, w, "directory entry");
        d.length = v.word(at + 5 * w, w, "directory entry");
        std::ostringstream where;
        where << "directory entry " << k << " (byte offset " << at << ")";
        if (d.nstr < 0 || d.nstr > static_cast<std::int64_t>(strings.size() - next_string))
            fail(F, where.str() + ": names " + std::to_string(d.nstr) + " strings, the string table has " +
                        std::to_string(strings.size() - next_string) + " left");
        d.s.assign(strings.begin() + static_cast<std::ptrdiff_t>(next_string),
                   strings.begin() + static_cast<std::ptrdiff_t>(next_string + d.nstr));
        next_string += static_cast<std::size_t>(d.nstr);
        if (d.offset < 0 || d.length < 0 || d.offset > strings_at || d.length > strings_at - d.offset)
            fail(F, where.str() + ": data at byte " + std::to_string(d.offset) + ", " + std::to_string(d.length) +
                        " bytes, outside the data part (bytes 16 to " + std::to_string(strings_at) + ")");
        if (d.type < 0 || d.type > 9) fail(F, where.str() + ": unknown directory type " + std::to_string(d.type));
        if ((d.type == 0 || d.type == 1 || d.type == 2 || d.type == 5 || d.type == 6 || d.type == 9) && d.nstr < 1)
            fail(F, where.str() + ": no name");
        if (d.type == 7 && d.nstr < 2) fail(F, where.str() + ": class definition without short and long name");
    }
    return dirs;
}

// The parameters (scalars and arrays) by name; the mesh dimension.
void MiliReader::read_parameters(const std::vector<Dir>& dirs) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    for (const Dir& d : dirs) {
        if (d.type != 5 && d.type != 6 && d.type != 9) continue;
        Param p;
        p.type = static_cast<int>(d.m1);
        p.array = d.m2 != 0;
        p.offset = d.offset;
        p.length = d.length;
        if (p.array) {
            const int tb = type_bytes(p.type);
            const std::int64_t order = v.i32(d.offset, "array parameter: rank");
            if (tb == 0 || order < 1 || order > 8) continue;  // not an array this reader uses
            std::int64_t n = 1;
            for (std::int64_t k = 0; k < order; ++k) {
                const std::int64_t dim = v.i32(d.offset + 4 + 4 * k, "array parameter: dimension");
                if (dim < 0) fail(F, "parameter \"" + d.s[0] + "\": negative dimension");
                p.dims.push_back(dim);
                n = mul(n, dim, F, "an array parameter");
            }
            p.offset = d.offset + 4 + 4 * order;
            const std::int64_t bytes = mul(n, tb, F, "an array parameter");
            if (bytes > d.offset + d.length - p.offset)
                fail(F, "parameter \"" + d.s[0] + "\": " + std::to_string(n) + " values do not fit its " +
                            std::to_string(d.length) + " bytes");
            p.length = bytes;
        }
        params_[d.s[0]] = p;
    }
    const std::int64_t dim = param_int("mesh dimensions", 3);
    if (dim != 2 && dim != 3) fail(F, "mesh dimensions " + std::to_string(dim) + " (2 or 3 are read)");
}

// The classes: definitions and identifiers, the objects the file backs with data, node
// coordinates, connectivity; then each class complete.
void MiliReader::read_classes(const std::vector<Dir>& dirs) {
    read_class_definitions(dirs);
    const std::vector<std::int64_t> backed = objects_with_data(dirs);
    std::vector<std::vector<double>> coords(classes_.size());
    std::vector<std::vector<unsigned char>> have(classes_.size());
    read_node_coordinates(dirs, backed, coords, have);
    std::vector<std::vector<unsigned char>> has_conn(classes_.size());
    read_connectivity(dirs, backed, has_conn);
    finish_classes(coords, have, has_conn);
}

int MiliReader::class_of(const std::string& name, const char* dir) const {
    const int c = find_class(name);
    if (c < 0) fail(a_file_, std::string(dir) + " of class \"" + name + "\", which no class definition names");
    return c;
}

void MiliReader::read_class_definitions(const std::vector<Dir>& dirs) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    for (const Dir& d : dirs) {
        if (d.type != 7) continue;
        if (find_class(d.s[0]) >= 0) fail(F, "class \"" + d.s[0] + "\" defined twice");
        MiliClass c;
        c.name = d.s[0];
        c.title = d.s[1];
        c.superclass = static_cast<int>(d.m2);
        c.nodes_per_element = mili_nodes_per_element(c.superclass);
        classes_.push_back(c);
    }
    for (const Dir& d : dirs) {
        if (d.type != 2) continue;
        MiliClass& c = classes_[static_cast<std::size_t>(class_of(d.s[0], "identifiers"))];
        const std::int64_t first = v.i32(d.offset + 4, "class identifiers"), last = v.i32(d.offset + 8, "class identifiers");
        if (d.length < 12) fail_at(F, d.offset, "class identifiers", 12, d.length);
        check_block(F, first, last, "identifiers of class " + c.name);
        c.count = std::max(c.count, last);
    }
}

std::vector<std::int64_t> MiliReader::objects_with_data(const std::vector<Dir>& dirs) const {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    // Objects the file backs with data (node coordinates, connectivity): ordinals must stay
    // within them, so that no allocation is larger than the file justifies.
    std::vector<std::int64_t> backed(classes_.size(), 0);
    for (const Dir& d : dirs) {
        if (d.type == 0) {
            const int ci = class_of(d.s[0], "nodes");
            const std::int64_t first = v.i32(d.offset, "node block"), last = v.i32(d.offset + 4, "node block");
            check_block(F, first, last, "nodes of class " + d.s[0]);
            backed[static_cast<std::size_t>(ci)] = add(backed[static_cast<std::size_t>(ci)], last - first + 1, F, "nodes");
        } else if (d.type == 1) {
            const int ci = class_of(d.s[0], "connectivity");
            const std::int64_t words = mili_nodes_per_element(classes_[static_cast<std::size_t>(ci)].superclass) + 2;
            if (d.m2 < 0 || mul(d.m2, 4 * words, F, "connectivity") > d.length)
                fail_at(F, d.offset, "connectivity of " + std::to_string(d.m2) + " elements of class " + d.s[0],
                        -1, d.offset + d.length);
            backed[static_cast<std::size_t>(ci)] = add(backed[static_cast<std::size_t>(ci)], d.m2, F, "connectivity");
        }
    }
    for (std::size_t ci = 0; ci < classes_.size(); ++ci) {
        const MiliClass& c = classes_[ci];
        if (backed[ci] > 0 && c.count > backed[ci])
            fail(F, "class " + c.name + ": identifiers up to " + std::to_string(c.count) + ", but data for " +
                        std::to_string(backed[ci]) + " objects");
        if (backed[ci] == 0 && c.count > (1 << 20))
            fail(F, "class " + c.name + ": " + std::to_string(c.count) + " objects without data (implausible)");
    }
    return backed;
}

void MiliReader::read_node_coordinates(const std::vector<Dir>& dirs, const std::vector<std::int64_t>& backed,
                                       std::vector<std::vector<double>>& coords,
                                       std::vector<std::vector<unsigned char>>& have) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    const std::int64_t dim = param_int("mesh dimensions", 3);
    for (const Dir& d : dirs) {
        if (d.type != 0) continue;
        const int ci = class_of(d.s[0], "nodes");
        const std::int64_t first = v.i32(d.offset, "node block"), last = v.i32(d.offset + 4, "node block");
        check_block(F, first, last, "nodes of class " + d.s[0]);
        check_backed(F, backed, ci, last, "nodes of class " + d.s[0]);
        const std::int64_t n = last - first + 1;
        const std::int64_t values = mul(n, dim, F, "node coordinates");
        const std::int64_t room = d.length - 8;
        const int fb = room == mul(values, 8, F, "node coordinates") && room != 4 * values ? 8 : 4;
        if (mul(values, fb, F, "node coordinates") > room)
            fail_at(F, d.offset + 8, "coordinates of nodes " + std::to_string(first) + ".." + std::to_string(last),
                    values * fb, d.offset + d.length);
        grow(classes_[static_cast<std::size_t>(ci)], last);
        auto& x = coords[static_cast<std::size_t>(ci)];
        auto& h = have[static_cast<std::size_t>(ci)];
        x.resize(static_cast<std::size_t>(3 * last), 0.0);
        h.resize(static_cast<std::size_t>(last), 0);
        for (std::int64_t k = 0; k < n; ++k) {
            const std::size_t node = static_cast<std::size_t>(first - 1 + k);
            h[node] = 1;
            for (int j = 0; j < dim; ++j) {
                const std::int64_t at = d.offset + 8 + (k * dim + j) * fb;
                x[3 * node + static_cast<std::size_t>(j)] = fb == 8 ? v.f64(at, "node coordinate") : v.f32(at, "node coordinate");
            }
        }
    }
}

void MiliReader::read_connectivity(const std::vector<Dir>& dirs, const std::vector<std::int64_t>& backed,
                                   std::vector<std::vector<unsigned char>>& has_conn) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    for (const Dir& d : dirs) {
        if (d.type != 1) continue;
        const int ci = class_of(d.s[0], "connectivity");
        MiliClass& c = classes_[static_cast<std::size_t>(ci)];
        const std::int64_t sc = v.i32(d.offset, "connectivity: superclass");
        const std::int64_t nb = v.i32(d.offset + 4, "connectivity: block count");
        if (sc != c.superclass) fail(F, "connectivity of class " + c.name + " has superclass " + std::to_string(sc) +
                                             ", its definition " + std::to_string(c.superclass));
        const int nn = c.nodes_per_element;
        if (nn == 0) fail(F, "connectivity of class " + c.name + ", whose superclass has no nodes");
        if (nb < 0 || mul(nb, 8, F, "connectivity blocks") > d.length - 8)
            fail_at(F, d.offset + 8, "connectivity blocks of class " + c.name, 8 * std::max<std::int64_t>(nb, 0),
                    d.offset + d.length);
        std::int64_t qty = 0;
        std::vector<std::pair<std::int64_t, std::int64_t>> blocks;
        for (std::int64_t b = 0; b < nb; ++b) {
            const std::int64_t first = v.i32(d.offset + 8 + 8 * b, "connectivity block"),
                               last = v.i32(d.offset + 12 + 8 * b, "connectivity block");
            check_block(F, first, last, "connectivity of class " + c.name);
            check_backed(F, backed, ci, last, "connectivity of class " + c.name);
            blocks.emplace_back(first, last);
            qty = add(qty, last - first + 1, F, "connectivity");
        }
        if (qty != d.m2) fail(F, "connectivity of class " + c.name + ": the blocks hold " + std::to_string(qty) +
                                     " elements, the directory entry says " + std::to_string(d.m2));
        const std::int64_t words = nn + 2;
        const std::int64_t at0 = d.offset + 8 + 8 * nb;
        if (mul(mul(qty, words, F, "connectivity"), 4, F, "connectivity") > d.offset + d.length - at0)
            fail_at(F, at0, "connectivity of class " + c.name, qty * words * 4, d.offset + d.length);
        std::int64_t e = 0;
        for (const auto& [first, last] : blocks) {
            grow(c, last);
            c.conn.resize(static_cast<std::size_t>(c.count * nn), 0);
            c.material.resize(static_cast<std::size_t>(c.count), 0);
            c.part.resize(static_cast<std::size_t>(c.count), 0);
            auto& hc = has_conn[static_cast<std::size_t>(ci)];
            hc.resize(static_cast<std::size_t>(c.count), 0);
            for (std::int64_t o = first - 1; o < last; ++o, ++e) {
                const std::int64_t at = at0 + e * words * 4;
                for (int j = 0; j < nn; ++j) {  // ordinals from 1 (INT_MIN kept: no overflow; refused below)
                    const std::int32_t ord = v.i32(at + 4 * j, "connectivity");
                    c.conn[static_cast<std::size_t>(o * nn + j)] = ord == std::numeric_limits<std::int32_t>::min() ? ord : ord - 1;
                }
                c.material[static_cast<std::size_t>(o)] = v.i32(at + 4 * nn, "material");
                c.part[static_cast<std::size_t>(o)] = v.i32(at + 4 * nn + 4, "part");
                hc[static_cast<std::size_t>(o)] = 1;
            }
        }
    }
}

// Every element with connectivity, every node with coordinates; the node, material and mesh
// classes.
void MiliReader::finish_classes(std::vector<std::vector<double>>& coords, std::vector<std::vector<unsigned char>>& have,
                                std::vector<std::vector<unsigned char>>& has_conn) {
    const std::string& F = a_file_;
    for (std::size_t ci = 0; ci < classes_.size(); ++ci) {
        MiliClass& c = classes_[ci];
        if (c.nodes_per_element > 0 && !c.conn.empty()) {
            c.conn.resize(static_cast<std::size_t>(c.count * c.nodes_per_element), 0);
            c.material.resize(static_cast<std::size_t>(c.count), 0);
            c.part.resize(static_cast<std::size_t>(c.count), 0);
            has_conn[ci].resize(static_cast<std::size_t>(c.count), 0);
            for (std::int64_t o = 0; o < c.count; ++o)
                if (!has_conn[ci][static_cast<std::size_t>(o)])
                    fail(F, "class " + c.name + ": element " + std::to_string(o + 1) + " of " + std::to_string(c.count) +
                                " has no connectivity");
        }
        if (c.superclass == kMiliNode && node_cls_ < 0) node_cls_ = static_cast<int>(ci);
        if (c.superclass == kMiliMat && mat_cls_ < 0) mat_cls_ = static_cast<int>(ci);
        if (c.superclass == kMiliMesh && mesh_cls_ < 0) mesh_cls_ = static_cast<int>(ci);
    }

    if (node_cls_ >= 0) {
        const MiliClass& c = classes_[static_cast<std::size_t>(node_cls_)];
        auto& h = have[static_cast<std::size_t>(node_cls_)];
        h.resize(static_cast<std::size_t>(c.count), 0);
        for (std::int64_t k = 0; k < c.count; ++k)
            if (!h[static_cast<std::size_t>(k)])
                fail(F, "node " + std::to_string(k + 1) + " of " + std::to_string(c.count) + " has no coordinates");
        x0_ = std::move(coords[static_cast<std::size_t>(node_cls_)]);
        x0_.resize(static_cast<std::size_t>(3 * c.count), 0.0);
    }
}

// The labels (TI parameters), appended in directory order; ordinals where a class has none.
void MiliReader::read_labels(const std::vector<Dir>& dirs) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    for (const Dir& d : dirs) {
        if (d.type != 9) continue;
        const std::string& name = d.s[0];
        int ci = -1;
        if (starts_with(name, "Node Labels")) ci = node_cls_;
        else if (starts_with(name, "Element Labels") && name.find("ElemIds") == std::string::npos)
            ci = find_class(class_in_label_name(name));
        if (ci < 0) continue;
        const Param& p = params_[name];
        if (!p.array || (p.type != kMiliInt && p.type != kMiliInt4))
            fail(F, "parameter \"" + name + "\" is not an array of 4-byte integers");
        auto& lab = classes_[static_cast<std::size_t>(ci)].labels;
        for (std::int64_t k = 0; k < p.length / 4; ++k) {
            lab.push_back(v.i32(p.offset + 4 * k, "label"));
            if (static_cast<std::int64_t>(lab.size()) > classes_[static_cast<std::size_t>(ci)].count)
                fail(F, "parameter \"" + name + "\": more labels than class " + classes_[static_cast<std::size_t>(ci)].name +
                            " has objects (" + std::to_string(classes_[static_cast<std::size_t>(ci)].count) + ")");
        }
    }
    for (MiliClass& c : classes_) {
        if (c.labels.empty()) {
            c.labels.resize(static_cast<std::size_t>(c.count));
            for (std::int64_t k = 0; k < c.count; ++k) c.labels[static_cast<std::size_t>(k)] = static_cast<int>(k + 1);
        } else if (static_cast<std::int64_t>(c.labels.size()) != c.count) {
            fail(F, "class " + c.name + ": " + std::to_string(c.labels.size()) + " labels for " + std::to_string(c.count) +
                        " objects");
        }
    }
}

// The integers and names of a variable dictionary or a record format, read in turn.
struct MiliReader::Tokens {
    const View& v;
    const std::string& file;
    const char* what;           // "variable dictionary" or "record format"
    std::int64_t entry;         // the directory entry's byte offset (for messages)
    std::int64_t first;         // the byte offset of the first integer
    std::int64_t ni;            // integers
    std::vector<std::string> ss;
    std::int64_t ii = 0;
    std::size_t si = 0;

    std::int64_t next_int() {
        if (ii >= ni) fail(file, std::string(what) + " at byte " + std::to_string(entry) + ": runs out of integers");
        return static_cast<std::int64_t>(v.i32(first + 4 * ii++, what));
    }
    const std::string& next_str() {
        if (si >= ss.size()) fail(file, std::string(what) + " at byte " + std::to_string(entry) + ": runs out of names");
        return ss[si++];
    }
};

// The state variables (directory type 3), then their components resolved by name.
void MiliReader::read_variables(const std::vector<Dir>& dirs) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    std::vector<std::vector<std::string>> comp_names;
    for (const Dir& d : dirs) {
        if (d.type != 3) continue;
        const std::int64_t iw = v.i32(d.offset, "variable dictionary: word count");
        const std::int64_t sb = v.i32(d.offset + 4, "variable dictionary: string bytes");
        if (iw < 2 || sb < 0 || mul(iw - 2, 4, F, "the variable dictionary") > d.length - 8 ||
            sb > d.length - 8 - 4 * (iw - 2))
            fail_at(F, d.offset, "variable dictionary of " + std::to_string(iw) + " words and " + std::to_string(sb) +
                                     " string bytes", -1, d.offset + d.length);
        const std::int64_t ni = iw - 2;
        Tokens t{v, F, "variable dictionary", d.offset, d.offset + 8, ni, split_strings(a_, d.offset + 8 + 4 * ni, sb)};
        while (t.ii < ni) read_variable(t, 0, comp_names);
    }
    for (std::size_t k = 0; k < vars_.size(); ++k)
        for (const std::string& cn : comp_names[k]) {
            const int c = find_variable(cn);
            if (c < 0) fail(F, "variable " + vars_[k].name + ": component \"" + cn + "\" is not defined");
            vars_[k].components.push_back(c);
        }
}

// One variable of a dictionary (and, first, the undefined components that follow it inline).
void MiliReader::read_variable(Tokens& t, int depth, std::vector<std::vector<std::string>>& comp_names) {
    const std::string& F = a_file_;
    if (depth > kMaxNesting) fail(F, "variable dictionary: variables nested deeper than " + std::to_string(kMaxNesting));
    MiliVariable var;
    var.aggregate = static_cast<int>(t.next_int());
    var.type = static_cast<int>(t.next_int());
    var.name = t.next_str();
    var.title = t.next_str();
    if (var.aggregate < 0 || var.aggregate > 3) fail(F, "variable " + var.name + ": aggregate type " + std::to_string(var.aggregate));
    if (type_bytes(var.type) == 0) fail(F, "variable " + var.name + ": data type " + std::to_string(var.type));
    if (var.aggregate == 2 || var.aggregate == 3) {
        const std::int64_t order = t.next_int();
        if (order < 1 || order > 8) fail(F, "variable " + var.name + ": array rank " + std::to_string(order));
        std::int64_t n = 1;
        for (std::int64_t k = 0; k < order; ++k) {
            const std::int64_t dm = t.next_int();
            if (dm < 0 || dm > 100000) fail(F, "variable " + var.name + ": array dimension " + std::to_string(dm));
            n = mul(n, dm, F, "an array variable");
            var.dims.push_back(static_cast<int>(dm));
        }
    }
    std::vector<std::string> comps;
    if (var.aggregate == 1 || var.aggregate == 3) {
        const std::int64_t ls = t.next_int();
        if (ls < 0 || ls > 100000) fail(F, "variable " + var.name + ": " + std::to_string(ls) + " components");
        for (std::int64_t k = 0; k < ls; ++k) comps.push_back(t.next_str());
        for (const std::string& cn : comps)
            if (find_variable(cn) < 0) read_variable(t, depth + 1, comp_names);  // an undefined component follows inline
    }
    vars_.push_back(var);
    comp_names.push_back(comps);
}

// The state-record format (directory type 4; one is read): its subrecords, which must add up to
// the size it declares.
void MiliReader::read_record_format(const std::vector<Dir>& dirs) {
    const std::string& F = a_file_;
    const View v(a_, F, big_endian_ != host_big_endian());
    int srec_dirs = 0;
    for (const Dir& d : dirs) {
        if (d.type != 4) continue;
        if (++srec_dirs > 1) fail(F, "several state-record formats (this reader reads one)");
        const std::int64_t declared = v.i32(d.offset + 8, "record format: size");
        const std::int64_t count = v.i32(d.offset + 12, "record format: subrecord count");
        const std::int64_t ni = d.m1 - 4, sb = d.m2;
        if (d.length < 16 || ni < 0 || sb < 0 || mul(ni, 4, F, "the record format") > d.length - 16 ||
            sb > d.length - 16 - 4 * ni || count < 0 || count > ni)
            fail_at(F, d.offset, "record format of " + std::to_string(count) + " subrecords", -1, d.offset + d.length);
        Tokens t{v, F, "record format", d.offset, d.offset + 16, ni, split_strings(a_, d.offset + 16 + 4 * ni, sb)};
        std::int64_t offset = 0;
        for (std::int64_t k = 0; k < count; ++k) {
            MiliSubrecord s = read_subrecord(t, k);
            s.offset = offset;
            offset = add(offset, s.bytes, F, "the state record");
            srecs_.push_back(std::move(s));
        }
        if (declared != offset)
            fail(F, "record format: the subrecords add up to " + std::to_string(offset) + " bytes, the header says " +
                        std::to_string(declared));
        record_bytes_ = offset;
    }
}

// Subrecord k of the record format: its variables, class and object blocks, and the slots of
// one object (each top variable flattened: vectors into their components, arrays point by point).
MiliSubrecord MiliReader::read_subrecord(Tokens& t, std::int64_t k) const {
    const std::string& F = a_file_;
    MiliSubrecord s;
    s.organization = static_cast<int>(t.next_int());
    const std::int64_t nsv = t.next_int(), nb = t.next_int();
    if (nsv < 0 || nsv > t.ni || nb < 0 || nb > t.ni)
        fail(F, "record format: subrecord " + std::to_string(k) + ": " + std::to_string(nsv) + " variables, " +
                    std::to_string(nb) + " blocks");
    std::vector<std::int64_t> raw;
    for (std::int64_t b = 0; b < 2 * nb; ++b) raw.push_back(t.next_int());
    s.name = t.next_str();
    s.class_name = t.next_str();
    for (std::int64_t j = 0; j < nsv; ++j) {
        const std::string& vn = t.next_str();
        const int vi = find_variable(vn);
        if (vi < 0) fail(F, "subrecord " + s.name + ": variable \"" + vn + "\" is not defined");
        s.variables.push_back(vi);
    }
    if (s.organization != 0 && s.organization != 1)
        fail(F, "subrecord " + s.name + ": organization " + std::to_string(s.organization));
    s.cls = class_of(s.class_name, ("subrecord " + s.name).c_str());
    const MiliClass& c = classes_[static_cast<std::size_t>(s.cls)];
    if (c.superclass == kMiliMesh) {
        s.objects = 1;
        s.blocks.emplace_back(0, 1);
    } else {
        for (std::int64_t b = 0; b < nb; ++b) {
            check_block(F, raw[2 * b], raw[2 * b + 1], "subrecord " + s.name);
            if (raw[2 * b + 1] > c.count)
                fail(F, "subrecord " + s.name + ": ordinals up to " + std::to_string(raw[2 * b + 1]) + ", class " +
                            c.name + " has " + std::to_string(c.count));
            s.blocks.emplace_back(raw[2 * b] - 1, raw[2 * b + 1] - raw[2 * b] + 1);
            s.objects = add(s.objects, raw[2 * b + 1] - raw[2 * b] + 1, F, "a subrecord");
        }
    }
    std::int64_t object_bytes = 0;
    for (std::size_t top = 0; top < s.variables.size(); ++top) {
        std::int64_t top_bytes = 0;
        std::vector<int> path;
        flatten(s, top, s.variables[top], -1, path, 0, object_bytes, top_bytes);
        s.top_bytes.push_back(top_bytes);
        if (s.organization == 0) {
            s.top_block.push_back(s.bytes);
            s.bytes = add(s.bytes, mul(top_bytes, s.objects, F, "a subrecord"), F, "a subrecord");
        } else {
            s.top_block.push_back(object_bytes);
        }
        object_bytes = add(object_bytes, top_bytes, F, "a subrecord");
    }
    s.object_bytes = object_bytes;
    if (s.organization == 1) s.bytes = mul(object_bytes, s.objects, F, "a subrecord");
    return s;
}

// Scalars per object of a variable (0 for empty vectors and arrays), at most 100000.
std::int64_t MiliReader::atoms_of(int var, int depth) const {
    const std::string& F = a_file_;
    if (depth > kMaxNesting) fail(F, "variable dictionary: variables nested deeper than " + std::to_string(kMaxNesting));
    const MiliVariable& mv = vars_[static_cast<std::size_t>(var)];
    std::int64_t n = 1;
    for (int dm : mv.dims) n = mul(n, dm, F, "an array variable");
    if (mv.aggregate == 1 || mv.aggregate == 3) {
        std::int64_t sum = 0;
        for (int comp : mv.components) sum = add(sum, atoms_of(comp, depth + 1), F, "a vector variable");
        n = mul(mv.aggregate == 3 ? n : 1, sum, F, "a vector variable");
    } else if (mv.aggregate == 0) {
        n = 1;
    }
    if (n > 100000) fail(F, "variable " + mv.name + ": more than 100000 values per object");
    return n;
}

// The slots of variable `var` (inside top variable `top` of subrecord s, at array point `point`,
// -1 outside arrays) appended to s.atoms; `top_bytes` counts the top variable's bytes so far.
void MiliReader::flatten(MiliSubrecord& s, std::size_t top, int var, int point, std::vector<int>& path, int depth,
                         std::int64_t object_bytes, std::int64_t& top_bytes) const {
    const std::string& F = a_file_;
    if (depth > kMaxNesting) fail(F, "subrecord " + s.name + ": variables nested too deeply");
    const MiliVariable& mv = vars_[static_cast<std::size_t>(var)];
    if (atoms_of(var, 0) == 0) return;
    path.push_back(var);
    std::int64_t n = 1;
    for (int dm : mv.dims) n = mul(n, dm, F, "a subrecord");
    for (std::int64_t p = 0; p < (mv.aggregate >= 2 ? n : 1); ++p) {
        const int pt = mv.aggregate >= 2 ? static_cast<int>(p) : point;
        if (mv.aggregate == 1 || mv.aggregate == 3) {
            for (int comp : mv.components) flatten(s, top, comp, pt, path, depth + 1, object_bytes, top_bytes);
        } else {
            MiliAtom a;
            a.leaf = var;
            a.top = s.variables[top];
            a.point = pt;
            a.top_pos = static_cast<int>(top);
            a.path = path;
            a.type = mv.type;
            a.offset = s.organization == 1 ? object_bytes + top_bytes : top_bytes;
            top_bytes = add(top_bytes, type_bytes(mv.type), F, "a subrecord");
            s.atoms.push_back(a);
            if (s.atoms.size() > 100000) fail(F, "subrecord " + s.name + ": more than 100000 values per object");
        }
    }
    path.pop_back();
}

// Every state lies inside its state file.
void MiliReader::check_state_maps() const {
    const std::string& F = a_file_;
    std::map<std::int32_t, std::int64_t> sizes;
    const std::vector<std::string> names = state_files();
    for (std::size_t k = 0; k < smaps_.size(); ++k) {
        const StateMap& m = smaps_[k];
        if (m.file < 0 || m.offset < 0 || !std::isfinite(m.time))
            fail(F, "state map " + std::to_string(k + 1) + ": file " + std::to_string(m.file) + ", offset " +
                        std::to_string(m.offset));
        std::string num = std::to_string(m.file);
        if (static_cast<int>(num.size()) < suffix_length_) num.insert(0, suffix_length_ - num.size(), '0');
        const std::string sf = base_ + num;
        auto it = sizes.find(m.file);
        if (it == sizes.end()) it = sizes.emplace(m.file, file_size(sf)).first;
        if (it->second < 0) fail(sf, "state file missing (state " + std::to_string(k + 1) + " is in it)");
        if (m.offset > it->second || record_bytes_ + 8 > it->second - m.offset)
            fail_at(sf, m.offset, "state " + std::to_string(k + 1) + " (time, record id, " + std::to_string(record_bytes_) +
                                      " bytes of subrecords)", record_bytes_ + 8, it->second);
    }
}

double MiliReader::time(int i) const {
    if (i < 0 || i >= num_states()) throw std::out_of_range("mili database: no state " + std::to_string(i));
    return smaps_[static_cast<std::size_t>(i)].time;
}

std::vector<char> MiliReader::read_record(int i) const {
    if (i < 0 || i >= num_states()) throw std::out_of_range("mili database: no state " + std::to_string(i));
    const StateMap& m = smaps_[static_cast<std::size_t>(i)];
    std::string num = std::to_string(m.file);
    if (static_cast<int>(num.size()) < suffix_length_) num.insert(0, suffix_length_ - num.size(), '0');
    const std::string sf = base_ + num;
    const std::int64_t size = file_size(sf);
    if (size < 0) fail(sf, "state file missing");
    if (m.offset > size || record_bytes_ + 8 > size - m.offset)
        fail_at(sf, m.offset, "state " + std::to_string(i + 1), record_bytes_ + 8, size);
    std::vector<char> rec(static_cast<std::size_t>(record_bytes_));
    std::ifstream in(sf, std::ios::binary);
    if (!in || !in.seekg(m.offset + 8) || (record_bytes_ > 0 && !in.read(rec.data(), record_bytes_)))
        fail(sf, "read error at byte offset " + std::to_string(m.offset));
    return rec;
}

double MiliReader::load(const std::vector<char>& rec, std::int64_t at, int type) const {
    const View v(rec, base_, big_endian_ != host_big_endian());
    switch (type) {
        case kMiliFloat: case kMiliFloat4: return v.f32(at, "state value");
        case kMiliFloat8: return v.f64(at, "state value");
        case kMiliInt: case kMiliInt4: return v.i32(at, "state value");
        case kMiliInt8: return static_cast<double>(v.i64(at, "state value"));
        default: return std::numeric_limits<double>::quiet_NaN();
    }
}

std::vector<MiliReader::Match> MiliReader::matches(int cls, const std::string& leaf, const std::string& container,
                                                   int point) const {
    std::vector<Match> out;
    for (std::size_t s = 0; s < srecs_.size(); ++s) {
        const MiliSubrecord& sr = srecs_[s];
        if (sr.cls != cls) continue;
        for (std::size_t a = 0; a < sr.atoms.size(); ++a) {
            const MiliAtom& at = sr.atoms[a];
            if (vars_[static_cast<std::size_t>(at.leaf)].name != leaf) continue;
            if (point >= 0 ? at.point != point : at.point > 0) continue;
            if (!container.empty()) {
                bool in = false;
                for (int p : at.path) in = in || vars_[static_cast<std::size_t>(p)].name == container;
                if (!in) continue;
            }
            out.push_back({static_cast<int>(s), static_cast<int>(a)});
            break;  // the first matching slot of this subrecord
        }
    }
    return out;
}

bool MiliReader::fill(const std::vector<char>& rec, const std::vector<Match>& m, std::vector<double>& out, int stride,
                      int slot) const {
    for (const Match& mt : m) {
        const MiliSubrecord& sr = srecs_[static_cast<std::size_t>(mt.srec)];
        const MiliAtom& a = sr.atoms[static_cast<std::size_t>(mt.atom)];
        const std::size_t top = static_cast<std::size_t>(a.top_pos);
        std::int64_t dense = 0;
        for (const auto& [first, n] : sr.blocks) {
            for (std::int64_t k = 0; k < n; ++k, ++dense) {
                const std::int64_t at = sr.organization == 1
                                            ? sr.offset + dense * sr.object_bytes + a.offset
                                            : sr.offset + sr.top_block[top] +
                                                  dense * sr.top_bytes[top] + a.offset;
                const std::size_t o = static_cast<std::size_t>((first + k) * stride + slot);
                if (o < out.size()) out[o] = load(rec, at, a.type);
            }
        }
    }
    return !m.empty();
}

bool MiliReader::result(int state, int cls, const std::string& leaf, std::vector<double>& out,
                        const std::string& container, int point) const {
    if (cls < 0 || cls >= static_cast<int>(classes_.size())) return false;
    const std::vector<Match> m = matches(cls, leaf, container, point);
    out.assign(static_cast<std::size_t>(classes_[static_cast<std::size_t>(cls)].count),
               std::numeric_limits<double>::quiet_NaN());
    if (m.empty()) return false;
    return fill(read_record(state), m, out, 1, 0);
}

int MiliReader::points(int cls, const std::string& leaf, const std::string& container) const {
    int n = 0;
    for (const MiliSubrecord& sr : srecs_) {
        if (sr.cls != cls) continue;
        for (const MiliAtom& at : sr.atoms) {
            if (vars_[static_cast<std::size_t>(at.leaf)].name != leaf) continue;
            bool in = container.empty();
            for (int p : at.path) in = in || vars_[static_cast<std::size_t>(p)].name == container;
            if (in) n = std::max(n, at.point + 1);
        }
    }
    return n;
}

namespace {

// Shell and beam record layout of the d3plot model (PlotLayout) the states are put into.
constexpr int kShellWords = 45;   // 3 layers x 7, 8 resultants, thickness, 2 element words, energy, 12 strains
constexpr int kBeamWords = 6;     // axial force, shear s, shear t, moment s, moment t, torsion

bool is_contact_segment(const MiliClass& c) {
    return c.name == "cseg" || c.title.find("Contact") != std::string::npos;
}

}  // namespace

void MiliReader::build_geometry() {
    const std::string& F = a_file_;
    PlotGeometry& g = geom_;
    g.title = param_string("title");
    g.x0 = x0_;
    const std::int64_t nn = static_cast<std::int64_t>(x0_.size() / 3);
    if (node_cls_ >= 0) g.node_user_ids = classes_[static_cast<std::size_t>(node_cls_)].labels;
    // materials: those of the elements drawn (DYNA3D numbers its sliding interfaces' sides
    // as further materials; the d3plot of the same model has none of them)
    int nmat = 0;
    for (std::size_t ci = 0; ci < classes_.size(); ++ci) {
        const MiliClass& c = classes_[ci];
        const int sc = c.superclass;
        const bool drawn = c.count > 0 && !c.conn.empty() &&
                           (sc == kMiliHex || sc == kMiliTet || sc == kMiliBeam || sc == kMiliTruss ||
                            ((sc == kMiliQuad || sc == kMiliTri) && !is_contact_segment(c)));
        if (!drawn) {
            if (c.nodes_per_element > 0 && c.count > 0) skipped_.push_back(c.name + " (" + c.title + ")");
            continue;
        }
        if (c.count > (1 << 28)) fail(F, "class " + c.name + ": " + std::to_string(c.count) + " elements");
        // the nodes used (a beam's third node, the orientation node, may be 0: none)
        const int used = (sc == kMiliBeam || sc == kMiliTruss) ? 2 : c.nodes_per_element;
        for (std::size_t k = 0; k < c.conn.size(); ++k) {
            const int n = c.conn[k];
            if (static_cast<int>(k % static_cast<std::size_t>(c.nodes_per_element)) < used && (n < 0 || n >= nn))
                fail(F, "class " + c.name + ": node ordinal " + std::to_string(std::int64_t(n) + 1) + " in the connectivity, the mesh has " +
                            std::to_string(nn) + " nodes");
        }
        for (std::int64_t e = 0; e < c.count; ++e) {
            const int m = c.material[static_cast<std::size_t>(e)];
            if (m < 1 || m > (1 << 20))
                fail(F, "class " + c.name + ": element " + std::to_string(c.labels[static_cast<std::size_t>(e)]) +
                            " has material " + std::to_string(m));
            nmat = std::max(nmat, m);
        }
        const int* cn = c.conn.data();
        const int k = c.nodes_per_element;
        std::vector<int>* nodes;
        std::vector<int>* mats;
        std::vector<int>* ids;
        if (sc == kMiliHex || sc == kMiliTet) {
            hex_cls_.emplace_back(static_cast<int>(ci), g.num_hexes());
            nodes = &g.hex_nodes, mats = &g.hex_material, ids = &g.hex_user_ids;
        } else if (sc == kMiliBeam || sc == kMiliTruss) {
            beam_cls_.emplace_back(static_cast<int>(ci), g.num_beams());
            nodes = &g.beam_nodes, mats = &g.beam_material, ids = &g.beam_user_ids;
        } else {
            shell_cls_.emplace_back(static_cast<int>(ci), g.num_shells());
            nodes = &g.shell_nodes, mats = &g.shell_material, ids = &g.shell_user_ids;
        }
        for (std::int64_t e = 0; e < c.count; ++e) {
            const int* q = cn + e * k;
            if (sc == kMiliHex) nodes->insert(nodes->end(), q, q + 8);
            else if (sc == kMiliTet) nodes->insert(nodes->end(), {q[0], q[1], q[2], q[2], q[3], q[3], q[3], q[3]});
            else if (sc == kMiliBeam || sc == kMiliTruss) nodes->insert(nodes->end(), q, q + 2);
            else if (sc == kMiliQuad) nodes->insert(nodes->end(), q, q + 4);
            else nodes->insert(nodes->end(), {q[0], q[1], q[2], q[2]});
            mats->push_back(c.material[static_cast<std::size_t>(e)]);
            ids->push_back(c.labels[static_cast<std::size_t>(e)]);
        }
    }
    if (nmat == 0 && mat_cls_ >= 0) nmat = static_cast<int>(classes_[static_cast<std::size_t>(mat_cls_)].count);
    g.num_materials = nmat;
    bool titled = false;
    for (int m = 1; m <= nmat; ++m) {
        g.part_titles.push_back(param_string("part_title_" + std::to_string(m)));
        titled = titled || !g.part_titles.back().empty();
    }
    if (!titled) g.part_titles.clear();
    layout_ = PlotLayout{};
    // beam integration points (an element-set array of stresses, as DYNA3D's es_1a): the
    // d3plot point blocks of 5 in LS-DYNA's order (shear stresses rs and tr, axial stress in the
    // beam's axes, plastic strain, axial strain: none; see state())
    for (const auto& bc : beam_cls_) layout_.beam_points = std::max(layout_.beam_points, points(bc.first, "sx"));
    if (!shell_cls_.empty()) {
        layout_.layers = 3;
        layout_.layer_words = 7;
        layout_.layer_stress = 0;
        layout_.layer_eps = 6;
        layout_.shell_forces = 21;
        layout_.shell_thickness = 29;
        layout_.shell_internal_energy = 32;
        layout_.shell_strain = 33;
    }
}

namespace {

// The beam's axes from its end nodes (r, node 1 to node 2) and a direction g for s (g projected
// normal to r; the global axis least aligned with r when g is missing or along r); t = r x s.
// False when the beam has no length.
bool beam_axes(const double* x1, const double* x2, const double* g, double r[3], double s[3], double t[3]) {
    double len = 0;
    for (int a = 0; a < 3; ++a) {
        r[a] = x2[a] - x1[a];
        len += r[a] * r[a];
    }
    len = std::sqrt(len);
    if (!(len > 0) || !std::isfinite(len)) return false;
    for (int a = 0; a < 3; ++a) r[a] /= len;
    auto project = [&](const double* d) {
        const double c = d[0] * r[0] + d[1] * r[1] + d[2] * r[2];
        double n = 0;
        for (int a = 0; a < 3; ++a) {
            s[a] = d[a] - c * r[a];
            n += s[a] * s[a];
        }
        n = std::sqrt(n);
        const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(n > 1e-6 * dn) || !std::isfinite(n)) return false;
        for (int a = 0; a < 3; ++a) s[a] /= n;
        return true;
    };
    if (!g || !project(g)) {
        int k = 0;
        for (int a = 1; a < 3; ++a)
            if (std::fabs(r[a]) < std::fabs(r[k])) k = a;
        const double e[3] = {k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0};
        project(e);
    }
    t[0] = r[1] * s[2] - r[2] * s[1];
    t[1] = r[2] * s[0] - r[0] * s[2];
    t[2] = r[0] * s[1] - r[1] * s[0];
    return true;
}

}  // namespace

// The values of a leaf into out[ordinal * stride + slot]; the mean over the points of an array
// when point == -2. False when the class does not write the leaf.
bool MiliReader::read_leaf(const std::vector<char>& rec, int cls, const std::string& leaf, const std::string& container,
                           int point, std::vector<double>& out, int stride, int slot) const {
    if (point != -2) return fill(rec, matches(cls, leaf, container, point), out, stride, slot);
    const int n = points(cls, leaf, container);
    if (n <= 1) return fill(rec, matches(cls, leaf, container, -1), out, stride, slot);
    const std::int64_t count = classes_[static_cast<std::size_t>(cls)].count;
    std::vector<double> sum(static_cast<std::size_t>(count), 0.0), one(static_cast<std::size_t>(count), 0.0);
    for (int p = 0; p < n; ++p) {
        fill(rec, matches(cls, leaf, container, p), one, 1, 0);
        for (std::int64_t e = 0; e < count; ++e) sum[static_cast<std::size_t>(e)] += one[static_cast<std::size_t>(e)] / n;
    }
    for (std::int64_t e = 0; e < count; ++e) {
        const std::size_t o = static_cast<std::size_t>(e * stride + slot);
        if (o < out.size()) out[o] = sum[static_cast<std::size_t>(e)];
    }
    return true;
}

// Node positions (initial + displacement), velocities and, when written, accelerations.
void MiliReader::read_node_state(const std::vector<char>& rec, PlotState& s) const {
    if (node_cls_ < 0) return;
    s.coords = x0_;
    const char* pos[3] = {"ux", "uy", "uz"};
    for (int j = 0; j < 3; ++j) read_leaf(rec, node_cls_, pos[j], "", -1, s.coords, 3, j);
    const char* vel[3] = {"vx", "vy", "vz"};
    const char* acc[3] = {"ax", "ay", "az"};
    std::vector<double> v(x0_.size(), 0.0), a(x0_.size(), 0.0);
    bool ha = false;
    for (int j = 0; j < 3; ++j) {
        read_leaf(rec, node_cls_, vel[j], "", -1, v, 3, j);
        ha = read_leaf(rec, node_cls_, acc[j], "", -1, a, 3, j) || ha;
    }
    s.vel = std::move(v);
    if (ha) s.acc = std::move(a);
}

// The family's alive flags from the classes' "sand" words (0: deleted); left empty when none is written.
void MiliReader::read_element_status(const std::vector<char>& rec, const std::vector<std::pair<int, int>>& cls,
                                     std::size_t n, std::vector<unsigned char>& alive) const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> sand(n, nan);
    bool any = false;
    for (const auto& [c, first] : cls) {
        std::vector<double> v(static_cast<std::size_t>(classes_[static_cast<std::size_t>(c)].count), nan);
        if (!read_leaf(rec, c, "sand", "", -1, v, 1, 0)) continue;
        any = true;
        std::copy(v.begin(), v.end(), sand.begin() + first);
    }
    if (!any) return;
    alive.assign(n, 1);
    for (std::size_t e = 0; e < n; ++e) alive[e] = sand[e] == 0.0 ? 0 : 1;
}

namespace {
const char* const kStressLeaves[6] = {"sx", "sy", "sz", "sxy", "syz", "szx"};
}  // namespace

// Solids: the six stresses and the plastic strain, means over the points.
void MiliReader::read_hex_state(const std::vector<char>& rec, PlotState& s) const {
    const std::size_t nh = static_cast<std::size_t>(geom_.num_hexes());
    if (nh == 0) return;
    s.stress.assign(6 * nh, 0.0);
    s.eps.assign(nh, 0.0);
    for (const auto& [c, first] : hex_cls_) {
        const std::size_t n = static_cast<std::size_t>(classes_[static_cast<std::size_t>(c)].count);
        std::vector<double> st(6 * n, 0.0), ep(n, 0.0);
        for (int j = 0; j < 6; ++j) read_leaf(rec, c, kStressLeaves[j], "", -2, st, 6, j);
        read_leaf(rec, c, "eps", "", -2, ep, 1, 0);
        std::copy(st.begin(), st.end(), s.stress.begin() + 6 * static_cast<std::ptrdiff_t>(first));
        std::copy(ep.begin(), ep.end(), s.eps.begin() + first);
    }
    read_element_status(rec, hex_cls_, nh, s.alive);
}

// A beam class's integration points (an element-set array such as DYNA3D's es_1a): DYNA3D writes
// their stresses in the global axes; each goes into the beam's axes (r from the state's node
// positions, s from the S vector svec when written) and into the d3plot point block, LS-DYNA's
// order: shear rs, shear tr, axial stress, plastic strain, axial strain (not written: 0).
void MiliReader::read_beam_points(const std::vector<char>& rec, int c, int first, int words, const PlotState& s,
                                  std::vector<double>& b) const {
    const std::size_t n = static_cast<std::size_t>(classes_[static_cast<std::size_t>(c)].count);
    const int np = std::min(layout_.beam_points, points(c, "sx"));
    if (np <= 0) return;
    const std::size_t npz = static_cast<std::size_t>(np);
    std::vector<double> st(6 * n * npz, 0.0), ep(n * npz, 0.0);
    for (int p = 0; p < np; ++p) {
        for (int j = 0; j < 6; ++j) read_leaf(rec, c, kStressLeaves[j], "", p, st, 6 * np, 6 * p + j);
        read_leaf(rec, c, "eps", "", p, ep, np, p);
    }
    std::vector<double> sv(3 * n, std::numeric_limits<double>::quiet_NaN());
    const char* svc[3] = {"svec_x", "svec_y", "svec_z"};
    bool has_sv = true;
    for (int j = 0; j < 3; ++j) has_sv = read_leaf(rec, c, svc[j], "", -1, sv, 3, j) && has_sv;
    for (std::size_t e = 0; e < n; ++e) {
        const std::size_t be = static_cast<std::size_t>(first) + e;
        const std::size_t n1 = static_cast<std::size_t>(geom_.beam_nodes[2 * be]), n2 = static_cast<std::size_t>(geom_.beam_nodes[2 * be + 1]);
        double r[3], sa[3], ta[3];
        if (3 * std::max(n1, n2) + 2 >= s.coords.size() ||
            !beam_axes(&s.coords[3 * n1], &s.coords[3 * n2], has_sv ? &sv[3 * e] : nullptr, r, sa, ta))
            continue;
        for (std::size_t p = 0; p < npz; ++p) {
            const double* q = &st[6 * (e * npz + p)];
            const double m[3][3] = {{q[0], q[3], q[5]}, {q[3], q[1], q[4]}, {q[5], q[4], q[2]}};
            auto proj = [&](const double* u, const double* w) {
                double x = 0;
                for (int a = 0; a < 3; ++a)
                    for (int k = 0; k < 3; ++k) x += u[a] * m[a][k] * w[k];
                return x;
            };
            double* o = &b[static_cast<std::size_t>(words) * e + kBeamWords + 5 * p];
            o[0] = proj(r, sa);
            o[1] = proj(ta, r);
            o[2] = proj(r, r);
            o[3] = ep[e * npz + p];
        }
    }
}

// Beams: the resultants and the integration points (read_beam_points).
void MiliReader::read_beam_state(const std::vector<char>& rec, PlotState& s) const {
    const std::size_t nb = static_cast<std::size_t>(geom_.num_beams());
    if (nb == 0) return;
    const int words = kBeamWords + 5 * layout_.beam_points;
    s.beam_vars.assign(static_cast<std::size_t>(words) * nb, 0.0);
    const char* res[kBeamWords] = {"axf", "sfs", "sft", "ms", "mt", "tor"};
    for (const auto& [c, first] : beam_cls_) {
        const std::size_t n = static_cast<std::size_t>(classes_[static_cast<std::size_t>(c)].count);
        std::vector<double> b(static_cast<std::size_t>(words) * n, 0.0);
        for (int j = 0; j < kBeamWords; ++j) read_leaf(rec, c, res[j], "", -1, b, words, j);
        read_beam_points(rec, c, first, words, s, b);
        std::copy(b.begin(), b.end(), s.beam_vars.begin() + words * static_cast<std::ptrdiff_t>(first));
    }
    read_element_status(rec, beam_cls_, nb, s.beam_alive);
}

// One shell class into its d3plot words: layers mid, inner, outer: named surfaces (stress_mid
// ...), else the points of an element-set array (inner the first, outer the last, mid the mean),
// else one stress; then resultants, thickness, extra words, internal energy and the strains.
void MiliReader::read_shell_class(const std::vector<char>& rec, int c, std::vector<double>& r) const {
    static const char* surf[3] = {"mid", "in", "out"};
    const int np = points(c, "sx");
    for (int L = 0; L < 3; ++L) {
        const std::string sc = std::string("stress_") + surf[L], ec = std::string("eeff_") + surf[L];
        const int pt = L == 0 ? -2 : (L == 1 ? 0 : std::max(0, np - 1));
        for (int j = 0; j < 6; ++j)
            if (!read_leaf(rec, c, kStressLeaves[j], sc, -1, r, kShellWords, 7 * L + j))
                read_leaf(rec, c, kStressLeaves[j], "", np > 1 ? pt : -1, r, kShellWords, 7 * L + j);
        if (!read_leaf(rec, c, ec, "", -1, r, kShellWords, 7 * L + 6))
            read_leaf(rec, c, "eps", "", np > 1 ? pt : -1, r, kShellWords, 7 * L + 6);
    }
    const char* res[8] = {"mxx", "myy", "mxy", "qxx", "qyy", "nxx", "nyy", "nxy"};
    for (int j = 0; j < 8; ++j) read_leaf(rec, c, res[j], "", -1, r, kShellWords, 21 + j);
    read_leaf(rec, c, "thick", "", -1, r, kShellWords, 29);
    read_leaf(rec, c, "edv1", "", -1, r, kShellWords, 30);
    read_leaf(rec, c, "edv2", "", -1, r, kShellWords, 31);
    read_leaf(rec, c, "inteng", "", -1, r, kShellWords, 32);
    const char* strain[6] = {"ex", "ey", "ez", "exy", "eyz", "ezx"};
    const int ns = points(c, "ex");
    for (int side = 0; side < 2; ++side)
        for (int j = 0; j < 6; ++j)
            if (!read_leaf(rec, c, strain[j], side == 0 ? "strain_in" : "strain_out", -1, r, kShellWords, 33 + 6 * side + j))
                read_leaf(rec, c, strain[j], "", ns > 1 ? (side == 0 ? 0 : ns - 1) : -1, r, kShellWords, 33 + 6 * side + j);
}

// Shells: each class's words (read_shell_class) and the alive flags.
void MiliReader::read_shell_state(const std::vector<char>& rec, PlotState& s) const {
    const std::size_t ns = static_cast<std::size_t>(geom_.num_shells());
    if (ns == 0) return;
    s.shell_vars.assign(kShellWords * ns, 0.0);
    for (const auto& [c, first] : shell_cls_) {
        const std::size_t n = static_cast<std::size_t>(classes_[static_cast<std::size_t>(c)].count);
        std::vector<double> r(kShellWords * n, 0.0);
        read_shell_class(rec, c, r);
        std::copy(r.begin(), r.end(), s.shell_vars.begin() + kShellWords * static_cast<std::ptrdiff_t>(first));
    }
    read_element_status(rec, shell_cls_, ns, s.shell_alive);
}

// The mesh classes' global energies and rigid-body velocity (finite values only).
void MiliReader::read_global_state(const std::vector<char>& rec, PlotState& s) const {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t c = 0; c < classes_.size(); ++c) {
        if (classes_[c].superclass != kMiliMesh) continue;
        std::vector<double> v(1, nan);
        auto one = [&](const char* leaf, double& dst) {
            v[0] = nan;
            if (read_leaf(rec, static_cast<int>(c), leaf, "", -1, v, 1, 0) && std::isfinite(v[0])) dst = v[0];
        };
        one("ke", s.kinetic_energy);
        one("pe", s.internal_energy);
        one("te", s.total_energy);
        one("rbvx", s.velocity[0]);
        one("rbvy", s.velocity[1]);
        one("rbvz", s.velocity[2]);
    }
}

// The per-material energies, velocities and masses of the first `materials` materials.
void MiliReader::read_material_state(const std::vector<char>& rec, int materials, PlotState& s) const {
    if (mat_cls_ < 0 || materials <= 0) return;
    const std::size_t nm = static_cast<std::size_t>(std::min(materials, 1 << 20));
    const std::size_t cm = static_cast<std::size_t>(classes_[static_cast<std::size_t>(mat_cls_)].count);
    auto per_mat = [&](const char* leaf, std::vector<double>& dst, int stride, int slot) {
        std::vector<double> v(cm, 0.0);
        read_leaf(rec, mat_cls_, leaf, "", -1, v, 1, 0);
        dst.resize(nm * static_cast<std::size_t>(stride), 0.0);
        for (std::size_t m = 0; m < std::min(nm, cm); ++m) dst[m * static_cast<std::size_t>(stride) + static_cast<std::size_t>(slot)] = v[m];
    };
    per_mat("matpe", s.mat_internal_energy, 1, 0);
    per_mat("matke", s.mat_kinetic_energy, 1, 0);
    per_mat("matxv", s.mat_velocity, 3, 0);
    per_mat("matyv", s.mat_velocity, 3, 1);
    per_mat("matzv", s.mat_velocity, 3, 2);
    per_mat("matmass", s.mat_mass, 1, 0);
    per_mat("mathe", s.mat_hourglass_energy, 1, 0);
}

PlotState MiliReader::state(int i, int materials) const {
    const std::vector<char> rec = read_record(i);
    PlotState s;
    s.time = smaps_[static_cast<std::size_t>(i)].time;
    read_node_state(rec, s);
    read_hex_state(rec, s);
    read_beam_state(rec, s);
    read_shell_state(rec, s);
    read_global_state(rec, s);
    read_material_state(rec, materials, s);
    return s;
}

// ---------------------------------------------------------------------------------------------
// Several processors merged by label.

std::vector<std::string> MiliDatabase::a_files(const std::string& path) {
    if (MiliReader::is_mili_file(path)) return {path};
    if ((path.empty() || path.back() != 'A') && MiliReader::is_mili_file(path + "A")) return {path + "A"};
    // NAME<digits>A: the processors' A files, by processor number
    namespace fs = std::filesystem;
    const fs::path p(path);
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    const std::string stem = p.filename().string();
    if (stem.empty()) return {};
    std::vector<std::pair<long long, std::string>> found;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() < stem.size() + 2 || name.compare(0, stem.size(), stem) != 0 || name.back() != 'A') continue;
        const std::string digits = name.substr(stem.size(), name.size() - stem.size() - 1);
        if (digits.empty() || digits.size() > 9 ||
            !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            continue;
        const std::string full = (dir / name).string();
        if (MiliReader::is_mili_file(full)) found.emplace_back(std::stoll(digits), full);
    }
    std::sort(found.begin(), found.end());
    std::vector<std::string> out;
    for (const auto& f : found) out.push_back(f.second);
    return out;
}

void MiliDatabase::open(const std::string& path) {
    *this = MiliDatabase();
    std::vector<std::string> files = a_files(path);
    if (files.empty()) files.push_back(path);  // MiliReader names what is missing
    for (const std::string& f : files) {
        parts_.push_back(std::make_unique<MiliReader>());
        parts_.back()->open(f);
    }
    num_states_ = parts_[0]->num_states();
    if (parts_.size() == 1) return;
    for (std::size_t k = 1; k < parts_.size(); ++k) {
        const MiliReader& r = *parts_[k];
        if (r.num_states() != num_states_)
            fail(files[k], std::to_string(r.num_states()) + " states, processor file " + files[0] + " has " +
                               std::to_string(num_states_));
        for (int i = 0; i < num_states_; ++i)
            if (std::fabs(r.time(i) - parts_[0]->time(i)) > 1e-6 * std::max(std::fabs(parts_[0]->time(i)), 1e-30))
                fail(files[k], "state " + std::to_string(i + 1) + " at time " + std::to_string(r.time(i)) + ", processor file " +
                                   files[0] + " at " + std::to_string(parts_[0]->time(i)));
    }
    // nodes and elements merged by label, in the order they first appear
    PlotGeometry& g = geom_;
    g.title = parts_[0]->geometry().title;
    std::map<int, int> nodes, hexes, beams, shells;
    for (const auto& pr : parts_) {
        const PlotGeometry& q = pr->geometry();
        node_map_.emplace_back();
        for (int n = 0; n < q.num_nodes(); ++n) {
            const int label = q.node_user_ids[static_cast<std::size_t>(n)];
            auto [it, fresh] = nodes.emplace(label, g.num_nodes());
            if (fresh) {
                g.x0.insert(g.x0.end(), q.x0.begin() + 3 * n, q.x0.begin() + 3 * n + 3);
                g.node_user_ids.push_back(label);
            }
            node_map_.back().push_back(it->second);
        }
        auto family = [&](const std::vector<int>& qn, const std::vector<int>& qm, const std::vector<int>& qid, int per,
                          std::vector<int>& gn, std::vector<int>& gm, std::vector<int>& gid, std::map<int, int>& seen,
                          std::vector<std::vector<int>>& map) {
            map.emplace_back();
            for (std::size_t e = 0; e < qm.size(); ++e) {
                auto [it, fresh] = seen.emplace(qid[e], static_cast<int>(gm.size()));
                if (fresh) {
                    for (int j = 0; j < per; ++j) gn.push_back(node_map_.back()[static_cast<std::size_t>(qn[e * per + j])]);
                    gm.push_back(qm[e]);
                    gid.push_back(qid[e]);
                }
                map.back().push_back(it->second);
            }
        };
        family(q.hex_nodes, q.hex_material, q.hex_user_ids, 8, g.hex_nodes, g.hex_material, g.hex_user_ids, hexes, hex_map_);
        family(q.beam_nodes, q.beam_material, q.beam_user_ids, 2, g.beam_nodes, g.beam_material, g.beam_user_ids, beams,
               beam_map_);
        family(q.shell_nodes, q.shell_material, q.shell_user_ids, 4, g.shell_nodes, g.shell_material, g.shell_user_ids,
               shells, shell_map_);
        g.num_materials = std::max(g.num_materials, q.num_materials);
        if (g.part_titles.empty()) g.part_titles = q.part_titles;
        const PlotLayout& L = pr->layout();
        if (L.layers > 0) layout_ = PlotLayout{L.solid_points, L.solid_point_words, L.solid_history, L.layers, L.layer_words,
                                               L.layer_stress, L.layer_eps, L.layer_history, L.shell_forces,
                                               L.shell_thickness, L.shell_strain, L.shell_internal_energy, L.tshell_strain,
                                               layout_.beam_points, layout_.beam_history};
        layout_.beam_points = std::max(layout_.beam_points, L.beam_points);
    }
    if (!g.part_titles.empty()) g.part_titles.resize(static_cast<std::size_t>(g.num_materials));
}

PlotState MiliDatabase::state(int i) const {
    if (parts_.size() == 1) return parts_[0]->state(i);
    const PlotGeometry& g = geom_;
    PlotState s;
    const std::size_t nn = static_cast<std::size_t>(g.num_nodes()), nh = static_cast<std::size_t>(g.num_hexes()),
                      nb = static_cast<std::size_t>(g.num_beams()), ns = static_cast<std::size_t>(g.num_shells());
    const std::size_t bw = 6 + 5 * static_cast<std::size_t>(layout_.beam_points), sw = 45;
    // Globals and per-material values: a value every processor writes alike is the model's
    // (DYNA3D's parallel runs write the kinetic energy so); otherwise each processor writes its
    // share and they are summed (internal and total energy, material values).
    std::vector<PlotState> qs;
    for (const auto& pr : parts_) qs.push_back(pr->state(i, g.num_materials));
    auto merged = [&](auto get) {
        double sum = 0.0;
        bool alike = true;
        for (const PlotState& q : qs) {
            sum += get(q);
            alike = alike && get(q) == get(qs[0]);
        }
        return alike ? get(qs[0]) : sum;
    };
    for (std::size_t p = 0; p < parts_.size(); ++p) {
        const PlotState& q = qs[p];
        if (p == 0) {
            s.time = q.time;
            s.coords = g.x0;
            s.vel.assign(3 * nn, 0.0);
            if (!q.acc.empty()) s.acc.assign(3 * nn, 0.0);
            s.stress.assign(6 * nh, 0.0);
            s.eps.assign(nh, 0.0);
            s.beam_vars.assign(bw * nb, 0.0);
            s.shell_vars.assign(sw * ns, 0.0);
            s.mat_internal_energy.assign(static_cast<std::size_t>(g.num_materials), 0.0);
            s.mat_kinetic_energy = s.mat_hourglass_energy = s.mat_mass = s.mat_internal_energy;
            s.mat_velocity.assign(3 * static_cast<std::size_t>(g.num_materials), 0.0);
        }
        const std::vector<int>& nm = node_map_[p];
        for (std::size_t n = 0; n < nm.size(); ++n)
            for (std::size_t j = 0; j < 3; ++j) {
                const std::size_t a = 3 * static_cast<std::size_t>(nm[n]) + j, b = 3 * n + j;
                if (b < q.coords.size()) s.coords[a] = q.coords[b];
                if (b < q.vel.size()) s.vel[a] = q.vel[b];
                if (b < q.acc.size() && a < s.acc.size()) s.acc[a] = q.acc[b];
            }
        auto alive = [](std::vector<unsigned char>& out, std::size_t n, const std::vector<unsigned char>& in, std::size_t e,
                        std::size_t to) {
            if (in.empty()) return;
            if (out.empty()) out.assign(n, 1);
            out[to] = in[e];
        };
        const std::vector<int>& hm = hex_map_[p];
        for (std::size_t e = 0; e < hm.size(); ++e) {
            const std::size_t to = static_cast<std::size_t>(hm[e]);
            for (std::size_t j = 0; j < 6 && 6 * e + j < q.stress.size(); ++j) s.stress[6 * to + j] = q.stress[6 * e + j];
            if (e < q.eps.size()) s.eps[to] = q.eps[e];
            alive(s.alive, nh, q.alive, e, to);
        }
        const std::vector<int>& bm = beam_map_[p];
        const std::size_t qbw = bm.empty() ? 0 : q.beam_vars.size() / bm.size();
        for (std::size_t e = 0; e < bm.size(); ++e) {
            const std::size_t to = static_cast<std::size_t>(bm[e]);
            for (std::size_t j = 0; j < std::min(bw, qbw); ++j) s.beam_vars[bw * to + j] = q.beam_vars[qbw * e + j];
            alive(s.beam_alive, nb, q.beam_alive, e, to);
        }
        const std::vector<int>& sm = shell_map_[p];
        for (std::size_t e = 0; e < sm.size(); ++e) {
            const std::size_t to = static_cast<std::size_t>(sm[e]);
            for (std::size_t j = 0; j < sw && sw * e + j < q.shell_vars.size(); ++j) s.shell_vars[sw * to + j] = q.shell_vars[sw * e + j];
            alive(s.shell_alive, ns, q.shell_alive, e, to);
        }
    }
    s.kinetic_energy = merged([](const PlotState& q) { return q.kinetic_energy; });
    s.internal_energy = merged([](const PlotState& q) { return q.internal_energy; });
    s.total_energy = merged([](const PlotState& q) { return q.total_energy; });
    for (std::size_t j = 0; j < 3; ++j) s.velocity[j] = merged([j](const PlotState& q) { return q.velocity[j]; });
    auto at = [](const std::vector<double>& v, std::size_t k) { return k < v.size() ? v[k] : 0.0; };
    for (std::size_t m = 0; m < s.mat_mass.size(); ++m) {
        s.mat_internal_energy[m] = merged([&](const PlotState& q) { return at(q.mat_internal_energy, m); });
        s.mat_kinetic_energy[m] = merged([&](const PlotState& q) { return at(q.mat_kinetic_energy, m); });
        s.mat_hourglass_energy[m] = merged([&](const PlotState& q) { return at(q.mat_hourglass_energy, m); });
        s.mat_mass[m] = merged([&](const PlotState& q) { return at(q.mat_mass, m); });
        for (std::size_t j = 0; j < 3; ++j) {  // alike: the model's; else the mass-weighted mean
            const std::size_t k = 3 * m + j;
            bool alike = true;
            double momentum = 0.0;
            for (const PlotState& q : qs) {
                alike = alike && at(q.mat_velocity, k) == at(qs[0].mat_velocity, k);
                momentum += at(q.mat_mass, m) * at(q.mat_velocity, k);
            }
            s.mat_velocity[k] = alike ? at(qs[0].mat_velocity, k) : s.mat_mass[m] > 0 ? momentum / s.mat_mass[m] : 0.0;
        }
    }
    return s;
}

bool MiliDatabase::locate(const std::string& cls_name, int label, int& part, int& cls, std::int64_t& ordinal) const {
    for (std::size_t p = 0; p < parts_.size(); ++p) {
        const int c = parts_[p]->find_class(cls_name);
        if (c < 0) continue;
        const auto& lab = parts_[p]->classes()[static_cast<std::size_t>(c)].labels;
        const auto it = std::find(lab.begin(), lab.end(), label);
        if (it == lab.end()) continue;
        part = static_cast<int>(p);
        cls = c;
        ordinal = it - lab.begin();
        return true;
    }
    return false;
}

bool MiliDatabase::has_object(const std::string& cls_name, int label) const {
    int p = 0, c = 0;
    std::int64_t o = 0;
    return locate(cls_name, label, p, c, o);
}

bool MiliDatabase::has_result(const std::string& cls_name, const std::string& leaf, const std::string& container,
                              int point) const {
    for (const auto& pr : parts_)
        if (pr->has_result(pr->find_class(cls_name), leaf, container, point)) return true;
    return false;
}

bool MiliDatabase::result(int state, const std::string& cls_name, int label, const std::string& leaf, double& value,
                          const std::string& container, int point) const {
    int p = 0, c = 0;
    std::int64_t o = 0;
    if (!locate(cls_name, label, p, c, o)) return false;
    std::vector<double> all;
    if (!parts_[static_cast<std::size_t>(p)]->result(state, c, leaf, all, container, point)) return false;
    value = all[static_cast<std::size_t>(o)];
    return true;
}

}  // namespace impact3d
