// Plot state database (d3plot family) writer and reader.  See plot_database.h and
// shared/spec/plot-database.md.
#include "common/plot_database.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace impact3d {

namespace {

constexpr double kEndMarker = -999999.0;
constexpr int kTitleRecordBytes = 72;
constexpr bool kHostBig = (std::endian::native == std::endian::big);

std::string errno_text(int e) { return std::generic_category().message(e); }

// ---------------------------------------------------------------------------------------------
// Encoding (writer): little-endian words of 4 or 8 bytes.

void put_bytes(std::vector<char>& b, const void* p, int n) {
    const char* c = static_cast<const char*>(p);
    if (kHostBig) {
        for (int k = n - 1; k >= 0; --k) b.push_back(c[k]);
    } else {
        b.insert(b.end(), c, c + n);
    }
}

void put_int(std::vector<char>& b, int ws, std::int64_t v) {
    if (ws == 4) {
        const std::int32_t x = static_cast<std::int32_t>(v);
        put_bytes(b, &x, 4);
    } else {
        put_bytes(b, &v, 8);
    }
}

void put_real(std::vector<char>& b, int ws, double v) {
    if (ws == 4) {
        // values beyond the float range become +-inf explicitly (the plain cast would be UB)
        const float x = (std::isfinite(v) && std::fabs(v) > std::numeric_limits<float>::max())
                            ? (v > 0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity())
                            : static_cast<float>(v);
        put_bytes(b, &x, 4);
    } else {
        put_bytes(b, &v, 8);
    }
}

// Text, blank padded / truncated to exactly nbytes.
void put_text(std::vector<char>& b, const std::string& s, std::size_t nbytes) {
    for (std::size_t k = 0; k < nbytes; ++k) b.push_back(k < s.size() ? s[k] : ' ');
}

// ---------------------------------------------------------------------------------------------
// Decoding (reader): bounds-checked views of a byte buffer that came from a file.

std::string trim_right(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();
    return s;
}

class Cursor {
public:
    Cursor(const char* data, std::int64_t size, std::string file, std::int64_t base, int ws,
           bool swap)
        : data_(data), size_(size), file_(std::move(file)), base_(base), ws_(ws), swap_(swap) {}

    std::int64_t pos() const { return pos_; }
    void seek(std::int64_t p) { pos_ = p; }
    std::int64_t remaining() const { return size_ - pos_; }
    bool has(std::int64_t nbytes) const { return nbytes >= 0 && pos_ <= size_ && nbytes <= size_ - pos_; }

    [[noreturn]] void fail(const std::string& what, std::int64_t nbytes) const {
        std::ostringstream os;
        os << "plot database " << file_ << ": truncated or corrupt at byte offset " << (base_ + pos_)
           << ": expected " << what;
        if (nbytes >= 0) os << " (" << nbytes << " bytes)";
        os << ", but the file has " << (base_ + size_) << " bytes";
        throw std::runtime_error(os.str());
    }
    void need(std::int64_t nbytes, const std::string& what) const {
        if (!has(nbytes)) fail(what, nbytes);
    }
    // Bytes needed for nwords words (overflow-safe); throws if not present.
    void need_words(std::int64_t nwords, const std::string& what) const {
        if (nwords < 0 || nwords > (std::numeric_limits<std::int64_t>::max() / 8)) fail(what, -1);
        need(nwords * ws_, what);
    }

    std::int64_t i(const char* what) {
        need(ws_, what);
        std::int64_t v;
        if (ws_ == 4) {
            std::int32_t x;
            load(&x, 4);
            v = x;
        } else {
            load(&v, 8);
        }
        return v;
    }
    double r(const char* what) {
        need(ws_, what);
        if (ws_ == 4) {
            float x;
            load(&x, 4);
            return x;
        }
        double x;
        load(&x, 8);
        return x;
    }
    std::string text(std::int64_t nbytes, const char* what) {
        need(nbytes, what);
        std::string s(data_ + pos_, data_ + pos_ + nbytes);
        pos_ += nbytes;
        return s;
    }
    void skip_words(std::int64_t nwords, const char* what) {
        need_words(nwords, what);
        pos_ += nwords * ws_;
    }
    std::int64_t abs_offset() const { return base_ + pos_; }
    int word_size() const { return ws_; }
    const std::string& file() const { return file_; }

private:
    void load(void* dst, int n) {
        char tmp[8];
        std::memcpy(tmp, data_ + pos_, n);
        if (swap_) std::reverse(tmp, tmp + n);
        std::memcpy(dst, tmp, n);
        pos_ += n;
    }
    const char* data_;
    std::int64_t size_;
    std::string file_;
    std::int64_t base_;
    int ws_;
    bool swap_;
    std::int64_t pos_ = 0;
};

std::vector<char> read_whole_file(const std::string& path) {
    std::error_code ec;
    const auto st = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(st))
        throw std::runtime_error("plot database " + path + ": cannot open: " +
                                 (ec ? ec.message() : std::string("no such file")));
    if (!std::filesystem::is_regular_file(st))
        throw std::runtime_error("plot database " + path + ": not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("plot database " + path + ": cannot open: " + errno_text(errno));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw std::runtime_error("plot database " + path + ": cannot determine the file size");
    in.seekg(0);
    std::vector<char> data(static_cast<std::size_t>(size));
    if (size > 0 && !in.read(data.data(), size))
        throw std::runtime_error("plot database " + path + ": read error");
    return data;
}

std::int64_t file_size_or(const std::string& path, std::int64_t dflt) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec) || ec) return dflt;
    const auto s = std::filesystem::file_size(path, ec);
    return ec ? dflt : static_cast<std::int64_t>(s);
}

// Bytes of the plot database family: the root file (root_bytes) and its members root01, ...
std::int64_t family_bytes(const std::string& root_path, std::size_t root_bytes) {
    std::int64_t bytes = static_cast<std::int64_t>(root_bytes);
    for (int m = 1;; ++m) {
        const std::int64_t s = file_size_or(PlotWriter::member_name(root_path, m), -1);
        if (s < 0) break;
        bytes += s;
    }
    return bytes;
}

// Reads exactly n bytes at offset; throws with file and offset otherwise.
std::vector<char> read_range(const std::string& path, std::int64_t offset, std::int64_t n,
                             const std::string& what) {
    const std::int64_t size = file_size_or(path, -1);
    if (size < 0) throw std::runtime_error("plot database " + path + ": cannot open (needed for " + what + ")");
    if (offset < 0 || n < 0 || offset > size || n > size - offset) {
        std::ostringstream os;
        os << "plot database " << path << ": truncated at byte offset " << offset << ": expected "
           << what << " (" << n << " bytes), but the file has " << size << " bytes";
        throw std::runtime_error(os.str());
    }
    std::ifstream in(path, std::ios::binary);
    std::vector<char> buf(static_cast<std::size_t>(n));
    if (!in || !in.seekg(offset) || (n > 0 && !in.read(buf.data(), n))) {
        std::ostringstream os;
        os << "plot database " << path << ": read error at byte offset " << offset << " reading " << what;
        throw std::runtime_error(os.str());
    }
    return buf;
}

// Overflow-checked arithmetic for sizes computed from (possibly corrupt) control words.
std::int64_t checked_mul(std::int64_t a, std::int64_t b, const std::string& file) {
    std::int64_t r;
    if (a < 0 || b < 0 || __builtin_mul_overflow(a, b, &r) || r > (std::int64_t{1} << 56))
        throw std::runtime_error("plot database " + file + ": implausible control words (size overflow)");
    return r;
}
std::int64_t checked_add(std::int64_t a, std::int64_t b, const std::string& file) {
    std::int64_t r;
    if (__builtin_add_overflow(a, b, &r) || r > (std::int64_t{1} << 56))
        throw std::runtime_error("plot database " + file + ": implausible control words (size overflow)");
    return r;
}

bool detect_word_size(const std::vector<char>& d, int ws, bool swap) {
    const std::size_t off = 14u * static_cast<unsigned>(ws);
    if (d.size() < off + ws) return false;
    char tmp[8];
    std::memcpy(tmp, d.data() + off, ws);
    if (swap) std::reverse(tmp, tmp + ws);
    double v;
    if (ws == 4) {
        float f;
        std::memcpy(&f, tmp, 4);
        v = f;
    } else {
        std::memcpy(&v, tmp, 8);
    }
    return v > 900.0 && v < 1000.0;
}

PlotControl parse_control(const std::vector<char>& d, const std::string& path) {
    PlotControl c;
    bool found = false;
    const std::pair<int, bool> tries[4] = {{4, false}, {8, false}, {4, true}, {8, true}};
    for (const auto& [ws, swap] : tries) {
        if (detect_word_size(d, ws, swap)) {
            c.word_size = ws;
            c.byte_swapped = (swap != kHostBig);
            found = true;
            break;
        }
    }
    if (!found) {
        std::ostringstream os;
        if (d.size() < 64 * 4)
            os << "plot database " << path << ": truncated at byte offset " << d.size()
               << ": expected the 64 control words (at least 256 bytes)";
        else
            os << "plot database " << path << ": not a d3plot file: the VERSION control word (word 14, "
               << "byte offset 56 or 112) is not a value in (900, 1000) as a 4- or 8-byte float in "
               << "either byte order";
        throw std::runtime_error(os.str());
    }
    const bool swap = c.byte_swapped != kHostBig;
    Cursor cur(d.data(), static_cast<std::int64_t>(d.size()), path, 0, c.word_size, swap);
    cur.need_words(64, "the 64 control words");
    c.title = trim_right(cur.text(10 * c.word_size, "title"));
    std::int64_t w[64] = {};
    for (int k = 10; k < 64; ++k) {
        if (k == 13) {
            cur.skip_words(1, "release");
        } else if (k == 14) {
            c.version = cur.r("version");
        } else {
            w[k] = cur.i("control word");
        }
    }
    c.runtime = w[10]; c.filetype = w[11]; c.source_version = w[12];
    c.ndim = w[15]; c.numnp = w[16]; c.icode = w[17]; c.nglbv = w[18];
    c.it = w[19]; c.iu = w[20]; c.iv = w[21]; c.ia = w[22];
    c.nel8 = w[23]; c.nummat8 = w[24]; c.numds = w[25]; c.numst = w[26]; c.nv3d = w[27];
    c.nel2 = w[28]; c.nummat2 = w[29]; c.nv1d = w[30];
    c.nel4 = w[31]; c.nummat4 = w[32]; c.nv2d = w[33];
    c.neiph = w[34]; c.neips = w[35]; c.maxint = w[36]; c.nmsph = w[37]; c.ngpsph = w[38];
    c.narbs = w[39]; c.nelt = w[40]; c.nummatt = w[41]; c.nv3dt = w[42];
    c.ioshl = {w[43], w[44], w[45], w[46]};
    c.ialemat = w[47]; c.ncfdv1 = w[48]; c.ncfdv2 = w[49]; c.nadapt = w[50]; c.nmmat = w[51];
    c.numfluid = w[52]; c.inn = w[53]; c.npefg = w[54]; c.nel48 = w[55]; c.idtdt = w[56];
    c.extra = w[57];
    c.nintf = w[63];
    return c;
}

[[noreturn]] void unsupported(const std::string& path, const std::string& what) {
    throw std::runtime_error("plot database " + path + ": unsupported d3plot content: " + what +
                             " (this reader does not read it)");
}

// ---------------------------------------------------------------------------------------------
// POSIX file output with errno-carrying errors.

[[noreturn]] void io_fail(const std::string& op, const std::string& file, int e, std::int64_t offset = -1) {
    std::ostringstream os;
    os << "plot database: " << op << " " << file;
    if (offset >= 0) os << " at byte offset " << offset;
    os << " failed: " << errno_text(e);
    throw std::runtime_error(os.str());
}

void pwrite_all(int fd, const char* p, std::size_t n, std::int64_t off, const std::string& file) {
    while (n > 0) {
        const ssize_t r = ::pwrite(fd, p, n, static_cast<off_t>(off));
        if (r < 0) {
            if (errno == EINTR) continue;
            io_fail("write to", file, errno, off);
        }
        if (r == 0) {
            std::ostringstream os;
            os << "plot database: write to " << file << " at byte offset " << off
               << " failed: short write (0 of " << n << " bytes written)";
            throw std::runtime_error(os.str());
        }
        p += r;
        n -= static_cast<std::size_t>(r);
        off += r;
    }
}

void fsync_or_throw(int fd, const std::string& file) {
    while (::fsync(fd) != 0) {
        if (errno == EINTR) continue;
        io_fail("fsync of", file, errno);
    }
}

std::string parent_dir(const std::string& path) {
    const std::filesystem::path p(path);
    const auto parent = p.parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

std::int64_t steady_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void fsync_dir_best_effort(const std::string& dir) {
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd < 0) return;
    (void)::fsync(dfd);
    ::close(dfd);
}

bool all_digits(const std::string& s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

template <class T>
void check_size(const std::vector<T>& v, std::size_t n, const char* what, bool allow_empty) {
    if (v.size() == n || (allow_empty && v.empty())) return;
    std::ostringstream os;
    os << "PlotWriter: " << what << " has " << v.size() << " entries, expected " << n
       << (allow_empty ? " (or none)" : "");
    throw std::invalid_argument(os.str());
}

}  // namespace

// =============================================================================================
// PlotWriter

PlotWriter::~PlotWriter() { close(); }

// RUNTIME (word 10): seconds since 1970, or SOURCE_DATE_EPOCH when set (reproducible files for
// regression suites that compare databases byte for byte).
static std::int64_t run_time_word() {
    if (const char* e = std::getenv("SOURCE_DATE_EPOCH")) {
        char* end = nullptr;
        long long v = std::strtoll(e, &end, 10);
        if (end != e && *end == '\0' && v >= 0) return v & 0x7fffffff;
    }
    return static_cast<std::int64_t>(std::time(nullptr)) & 0x7fffffff;
}

// Restart: keep the root file and the first keep_states states of an existing family (laid out
// by the same member rule as write_state), drop everything after them, and continue appending.
void PlotWriter::resume_members(int keep) {
    if (file_size_or(root_, -1) < 0)
        throw std::runtime_error("plot database " + root_ + ": cannot resume: the root file is missing");
    const std::int64_t per = std::max<std::int64_t>(1, (limit_words_ - 1) / state_words_);
    const int members = keep == 0 ? 0 : static_cast<int>((keep + per - 1) / per);
    const int in_last = keep == 0 ? 0 : static_cast<int>(keep - (members - 1) * per);
    // every kept member must exist and hold its states
    for (int m = 1; m <= members; ++m) {
        const std::int64_t need = (m < members ? per : in_last) * state_words_ * ws_;
        if (file_size_or(member_name(root_, m), -1) < need + ws_)
            throw std::runtime_error("plot database " + member_name(root_, m) +
                                     ": cannot resume: fewer states than the restart dump expects");
    }
    // remove later members (and temporaries) so no reader continues into them
    for (int m = members + 1;; ++m) {
        const std::string name = member_name(root_, m);
        std::error_code ec;
        std::filesystem::remove(name + ".tmp", ec);
        if (!std::filesystem::exists(name, ec)) break;
        std::filesystem::remove(name, ec);
        if (ec) throw std::runtime_error("plot database: cannot remove " + name + ": " + ec.message());
    }
    members_ = members;
    states_in_member_ = in_last;
    states_written_ = keep;
    marker_pos_ = static_cast<std::int64_t>(in_last) * state_words_ * ws_;
    root_written_ = true;
    if (members == 0) return;
    const std::string name = member_name(root_, members);
    const int fd = ::open(name.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) io_fail("open of", name, errno);
    std::vector<char> mk;
    put_real(mk, ws_, kEndMarker);
    try {
        pwrite_all(fd, mk.data(), mk.size(), marker_pos_, name);
        if (::ftruncate(fd, static_cast<off_t>(marker_pos_ + ws_)) != 0) io_fail("truncate of", name, errno);
        fsync_or_throw(fd, name);
    } catch (...) {
        ::close(fd);
        throw;
    }
    fd_ = fd;
}

void PlotWriter::sync() {
    if (fd_ >= 0 && unsynced_) {
        fsync_or_throw(fd_, member_name(root_, members_));
        ++syncs_;
    }
    unsynced_ = false;
    last_sync_ns_ = steady_ns();
}

void PlotWriter::close() noexcept {
    if (fd_ >= 0 && unsynced_) (void)::fsync(fd_);
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    unsynced_ = false;
    root_written_ = false;
}

std::string PlotWriter::member_name(const std::string& root_path, int member) {
    if (member <= 0) return root_path;
    char num[16];
    std::snprintf(num, sizeof num, "%02d", member);
    return root_path + num;
}

void PlotWriter::open(const std::string& root_path, const PlotGeometry& g, int word_size,
                      std::int64_t member_size_limit_words) {
    open_impl(root_path, g, word_size, member_size_limit_words, -1);
}

void PlotWriter::resume(const std::string& root_path, const PlotGeometry& g, int word_size,
                        std::int64_t member_size_limit_words, int keep_states) {
    if (keep_states < 0) throw std::invalid_argument("PlotWriter::resume: keep_states must be >= 0");
    open_impl(root_path, g, word_size, member_size_limit_words, keep_states);
}

namespace {

// The parts that elements of one family use (NUMMAT4 for shells, NUMMAT2 for beams), each
// element's material checked to be in 1..nmat.
std::int64_t parts_used(const std::vector<int>& material, int nmat, const char* what) {
    std::vector<char> used(static_cast<std::size_t>(nmat) + 1, 0);
    for (std::size_t e = 0; e < material.size(); ++e) {
        if (material[e] < 1 || material[e] > nmat)
            throw std::invalid_argument("PlotWriter: " + std::string(what) + " " + std::to_string(e) +
                                        " material not in 1.." + std::to_string(nmat));
        used[static_cast<std::size_t>(material[e])] = 1;
    }
    std::int64_t n = 0;
    for (char c : used) n += c;
    return n;
}

// Node indices of `nodes_per` node elements within 0..numnp-1.
void check_element_nodes(const std::vector<int>& nodes, std::size_t nodes_per, std::size_t numnp, const char* what) {
    for (std::size_t k = 0; k < nodes.size(); ++k)
        if (nodes[k] < 0 || static_cast<std::size_t>(nodes[k]) >= numnp)
            throw std::invalid_argument("PlotWriter: " + std::string(what) + " " + std::to_string(k / nodes_per) +
                                        " node index out of range");
}

// The connectivity of the root file: solids (IX8), beams (IX2), shells (IX4), each with its
// material.
void put_connectivity(std::vector<char>& b, int ws, const PlotGeometry& g) {
    const std::size_t nel8 = g.hex_material.size(), nel2 = g.beam_material.size(), nel4 = g.shell_material.size();
    for (std::size_t e = 0; e < nel8; ++e) {
        for (int k = 0; k < 8; ++k) put_int(b, ws, g.hex_nodes[8 * e + k] + 1);
        put_int(b, ws, g.hex_material[e]);
    }
    for (std::size_t e = 0; e < nel2; ++e) {  // IX2 (after solids, thick shells: none): n1 n2 n3, two unused, material
        put_int(b, ws, g.beam_nodes[2 * e] + 1);
        put_int(b, ws, g.beam_nodes[2 * e + 1] + 1);
        put_int(b, ws, g.beam_orientation.empty() || g.beam_orientation[e] < 0 ? 0 : g.beam_orientation[e] + 1);
        put_int(b, ws, 0);
        put_int(b, ws, 0);
        put_int(b, ws, g.beam_material[e]);
    }
    for (std::size_t e = 0; e < nel4; ++e) {  // IX4 (after solids, thick shells, beams)
        for (int k = 0; k < 4; ++k) put_int(b, ws, g.shell_nodes[4 * e + k] + 1);
        put_int(b, ws, g.shell_material[e]);
    }
}

// The NARBS section, NSORT < 0 variant (16-word header + part id arrays).
void put_user_ids(std::vector<char>& b, int ws, const PlotGeometry& g, const std::vector<int>& pids) {
    const std::int64_t np = static_cast<std::int64_t>(g.x0.size() / 3), n8 = static_cast<std::int64_t>(g.hex_material.size());
    const std::int64_t n2 = static_cast<std::int64_t>(g.beam_material.size()), n4 = static_cast<std::int64_t>(g.shell_material.size());
    const std::size_t numnp = g.x0.size() / 3, nel8 = g.hex_material.size(), nel2 = g.beam_material.size(), nel4 = g.shell_material.size();
    const int nmat = g.num_materials;
    const std::int64_t nsort = 100;
    const std::int64_t nsrh = nsort + np, nsrb = nsrh + n8, nsrs = nsrb + n2, nsrt = nsrs + n4;
    const std::int64_t nsrma = nsrt, nsrmu = nsrma + nmat, nsrmp = nsrmu + nmat;
    const std::int64_t hdr[16] = {-nsort, nsrh, nsrb, nsrs, nsrt, np, n8, n2, n4, 0,
                                  nsrma, nsrmu, nsrmp, nmat, 0, nmat};
    for (std::int64_t v : hdr) put_int(b, ws, v);
    for (std::size_t n = 0; n < numnp; ++n)
        put_int(b, ws, g.node_user_ids.empty() ? static_cast<std::int64_t>(n + 1) : g.node_user_ids[n]);
    for (std::size_t e = 0; e < nel8; ++e)
        put_int(b, ws, g.hex_user_ids.empty() ? static_cast<std::int64_t>(e + 1) : g.hex_user_ids[e]);
    for (std::size_t e = 0; e < nel2; ++e)  // beams, then shells
        put_int(b, ws, g.beam_user_ids.empty() ? static_cast<std::int64_t>(e + 1) : g.beam_user_ids[e]);
    for (std::size_t e = 0; e < nel4; ++e)
        put_int(b, ws, g.shell_user_ids.empty() ? static_cast<std::int64_t>(e + 1) : g.shell_user_ids[e]);
    for (int p : pids) put_int(b, ws, p);   // NORDER (ascending)
    for (int p : pids) put_int(b, ws, p);   // NSRMU (input order)
    for (int p = 1; p <= nmat; ++p) put_int(b, ws, p);  // NSRMP (cross reference)
}

// The end marker, the title records (90001 part titles first: VTK expects them right after the
// marker; then 90000, the model title) and the closing marker.
void put_titles(std::vector<char>& b, int ws, const PlotGeometry& g, const std::vector<int>& pids) {
    const int nmat = g.num_materials;
    put_real(b, ws, kEndMarker);
    put_int(b, ws, 90001);
    put_int(b, ws, nmat);
    for (int p = 0; p < nmat; ++p) {
        put_int(b, ws, pids[p]);
        put_text(b, g.part_titles.empty() ? "part " + std::to_string(pids[p]) : g.part_titles[p],
                 kTitleRecordBytes);
    }
    put_int(b, ws, 90000);
    put_text(b, g.title, kTitleRecordBytes);
    put_real(b, ws, kEndMarker);
}

// On resume: the family must be this model's (the root file the writer would write now, but
// for the run-time word, word 10).
void check_root_to_resume(const std::string& root_path, const std::vector<char>& b, int ws) {
    const bool exists = file_size_or(root_path, -1) >= 0;  // (missing: resume_members says so)
    const std::vector<char> old = exists ? read_whole_file(root_path) : std::vector<char>{};
    const std::size_t rt0 = 10u * static_cast<std::size_t>(ws), rt1 = rt0 + static_cast<std::size_t>(ws);
    const bool same = old.size() == b.size() && std::equal(old.begin(), old.begin() + static_cast<std::ptrdiff_t>(rt0), b.begin()) &&
                      std::equal(old.begin() + static_cast<std::ptrdiff_t>(rt1), old.end(), b.begin() + static_cast<std::ptrdiff_t>(rt1));
    if (exists && !same)
        throw std::runtime_error("plot database " + root_path + ": cannot resume: the root file does not belong to "
                                 "this model (control words, geometry, ids or titles differ)");
}

// Removes stale family members of an earlier run (root + digits, and their .tmp), so that no
// reader continues into them.
void remove_stale_members(const std::string& root_path, const std::string& dir) {
    const std::string base = std::filesystem::path(root_path).filename().string();
    std::error_code ec;
    std::vector<std::filesystem::path> stale;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= base.size() || name.compare(0, base.size(), base) != 0) continue;
        std::string rest = name.substr(base.size());
        if (rest.size() > 4 && rest.compare(rest.size() - 4, 4, ".tmp") == 0) rest.resize(rest.size() - 4);
        if (all_digits(rest)) stale.push_back(it->path());
    }
    for (const auto& p : stale) {
        std::error_code rec;
        std::filesystem::remove(p, rec);
        if (rec) throw std::runtime_error("plot database: cannot remove stale family member " + p.string() +
                                          ": " + rec.message());
    }
}

// Writes the root file, synced.
void write_root_file(const std::string& root_path, const std::string& dir, const std::vector<char>& b) {
    const int fd = ::open(root_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) io_fail("open of", root_path, errno);
    try {
        pwrite_all(fd, b.data(), b.size(), 0, root_path);
        fsync_or_throw(fd, root_path);
    } catch (...) {
        ::close(fd);
        throw;
    }
    if (::close(fd) != 0) io_fail("close of", root_path, errno);
    fsync_dir_best_effort(dir);
}

}  // namespace

void PlotWriter::open_impl(const std::string& root_path, const PlotGeometry& g, int word_size,
                           std::int64_t member_size_limit_words, int keep_states) {
    close();
    check_geometry(g, word_size, member_size_limit_words);
    set_sizes(g, word_size, member_size_limit_words);
    root_ = root_path;
    x0_ = g.x0;
    members_ = 0;
    states_in_member_ = 0;
    states_written_ = 0;
    marker_pos_ = 0;
    last_sync_ns_ = steady_ns();

    const std::string dir = parent_dir(root_path);
    const std::vector<char> b = root_file(g);
    if (keep_states >= 0) {
        check_root_to_resume(root_path, b, ws_);
        resume_members(keep_states);
        return;
    }
    remove_stale_members(root_path, dir);
    write_root_file(root_path, dir, b);
    root_written_ = true;
}

// What the writer refuses (std::invalid_argument): word sizes, sizes of the geometry's arrays,
// node and material indices out of range, implausible counts.
void PlotWriter::check_geometry(const PlotGeometry& g, int word_size, std::int64_t member_size_limit_words) {
    if (word_size != 4 && word_size != 8)
        throw std::invalid_argument("PlotWriter: word size must be 4 or 8, got " + std::to_string(word_size));
    if (member_size_limit_words < 1)
        throw std::invalid_argument("PlotWriter: member size limit must be positive");
    if (g.x0.size() % 3 != 0) throw std::invalid_argument("PlotWriter: x0 size is not a multiple of 3");
    if (!g.tshell_material.empty())
        throw std::invalid_argument("PlotWriter: writes solids, beams and shells only (the geometry has thick shells)");
    const std::size_t numnp = g.x0.size() / 3;
    const std::size_t nel8 = g.hex_material.size();
    const std::size_t nel4 = g.shell_material.size();
    const std::size_t nel2 = g.beam_material.size();
    const int nmat = g.num_materials;
    if (numnp > 100000000u || nel8 > 100000000u) throw std::invalid_argument("PlotWriter: model too large");
    if (nmat < 0 || (nel8 > 0 && nmat < 1))
        throw std::invalid_argument("PlotWriter: num_materials must be >= 1 when there are solids");
    check_size(g.hex_nodes, 8 * nel8, "hex_nodes", false);
    check_size(g.node_user_ids, numnp, "node_user_ids", true);
    check_size(g.hex_user_ids, nel8, "hex_user_ids", true);
    check_size(g.shell_nodes, 4 * nel4, "shell_nodes", false);
    check_size(g.shell_user_ids, nel4, "shell_user_ids", true);
    if (nel4 > 100000000u) throw std::invalid_argument("PlotWriter: model too large");
    check_element_nodes(g.shell_nodes, 4, numnp, "shell");
    parts_used(g.shell_material, nmat, "shell");
    if (nel2 > 100000000u) throw std::invalid_argument("PlotWriter: model too large");
    check_size(g.beam_nodes, 2 * nel2, "beam_nodes", false);
    check_size(g.beam_user_ids, nel2, "beam_user_ids", true);
    check_size(g.beam_orientation, nel2, "beam_orientation", true);
    if (g.beam_points < 0 || g.beam_points > 10000) throw std::invalid_argument("PlotWriter: implausible number of beam points");
    check_element_nodes(g.beam_nodes, 2, numnp, "beam");
    for (int n : g.beam_orientation)
        if (n >= 0 && static_cast<std::size_t>(n) >= numnp) throw std::invalid_argument("PlotWriter: beam orientation node out of range");
    parts_used(g.beam_material, nmat, "beam");
    check_size(g.part_titles, static_cast<std::size_t>(nmat), "part_titles", true);
    check_size(g.part_user_ids, static_cast<std::size_t>(nmat), "part_user_ids", true);
    for (std::size_t k = 0; k < g.hex_nodes.size(); ++k)
        if (g.hex_nodes[k] < 0 || static_cast<std::size_t>(g.hex_nodes[k]) >= numnp)
            throw std::invalid_argument("PlotWriter: hex " + std::to_string(k / 8) + " node index " +
                                        std::to_string(g.hex_nodes[k]) + " out of range");
    for (std::size_t e = 0; e < nel8; ++e)
        if (g.hex_material[e] < 1 || g.hex_material[e] > nmat)
            throw std::invalid_argument("PlotWriter: hex " + std::to_string(e) + " material " +
                                        std::to_string(g.hex_material[e]) + " not in 1.." + std::to_string(nmat));
    for (std::size_t p = 1; p < g.part_user_ids.size(); ++p)
        if (g.part_user_ids[p] <= g.part_user_ids[p - 1])
            throw std::invalid_argument("PlotWriter: part_user_ids must be strictly ascending");
    if (g.num_rigid_walls < 0 || g.num_rigid_walls > 100000)
        throw std::invalid_argument("PlotWriter: implausible number of rigid walls");
    if (g.num_interfaces < 0 || g.num_interfaces > 100000)
        throw std::invalid_argument("PlotWriter: implausible number of sliding interfaces");
    if (g.num_solid_history < 0 || g.num_solid_history > 1000)
        throw std::invalid_argument("PlotWriter: implausible number of solid history values");
}

void PlotWriter::set_sizes(const PlotGeometry& g, int word_size, std::int64_t member_size_limit_words) {
    const std::size_t numnp = g.x0.size() / 3;
    const std::size_t nel8 = g.hex_material.size();
    const std::size_t nel4 = g.shell_material.size();
    const std::size_t nel2 = g.beam_material.size();
    const int nmat = g.num_materials;
    ws_ = word_size;
    limit_words_ = member_size_limit_words;
    numnp_ = static_cast<int>(numnp);
    nel8_ = static_cast<int>(nel8);
    nel4_ = static_cast<int>(nel4);
    nel2_ = static_cast<int>(nel2);
    nv1d_ = nel2 > 0 ? 6 + 5 * g.beam_points : 0;
    nmmat_ = nmat;
    nrw_ = g.num_rigid_walls;
    nif_ = g.num_interfaces;
    nglbv_ = 6 + 7 * static_cast<std::int64_t>(nmat) + nrw_ + 3 * static_cast<std::int64_t>(nif_);
    neiph_ = g.num_solid_history;
    // time, globals, coords + vel + acc, 7 + NEIPH words and one deletion flag per solid, the
    // beam records and one deletion flag per beam, the shell records and one deletion flag per
    // shell
    state_words_ = 1 + nglbv_ + 9 * static_cast<std::int64_t>(numnp) + (8 + neiph_) * static_cast<std::int64_t>(nel8) +
                   (nv1d_ + 1) * static_cast<std::int64_t>(nel2) + (kShellPlotVars + 1) * static_cast<std::int64_t>(nel4);
}

// The root file: control words, geometry, user ids, titles.
std::vector<char> PlotWriter::root_file(const PlotGeometry& g) const {
    const int ws = ws_;
    std::vector<char> b;
    put_control_words(b, g);
    for (double x : g.x0) put_real(b, ws, x);
    put_connectivity(b, ws, g);
    std::vector<int> pids = g.part_user_ids;
    if (pids.empty())
        for (int p = 1; p <= nmmat_; ++p) pids.push_back(p);
    put_user_ids(b, ws, g, pids);
    put_titles(b, ws, g, pids);
    return b;
}

// The 64 control words (title, run time, FILETYPE, NDIM, counts, NARBS, IOSHL, NMMAT, word 63).
void PlotWriter::put_control_words(std::vector<char>& b, const PlotGeometry& g) const {
    const int ws = ws_;
    const int nmat = g.num_materials;
    const std::int64_t nummat4 = parts_used(g.shell_material, nmat, "shell");
    const std::int64_t nummat2 = parts_used(g.beam_material, nmat, "beam");
    std::string title40 = g.title;
    put_text(b, title40, 10u * ws);
    for (int k = 10; k < 64; ++k) {
        std::int64_t v = 0;
        switch (k) {
            case 10: v = run_time_word(); break;
            case 11: v = 1; break;        // FILETYPE d3plot
            case 15: v = 4; break;        // NDIM
            case 16: v = numnp_; break;   // NUMNP
            case 17: v = 6; break;        // ICODE
            case 18: v = nglbv_; break;   // NGLBV
            case 20: case 21: case 22: v = 1; break;  // IU IV IA
            case 23: v = nel8_; break;    // NEL8
            case 24: v = nmmat_ - nummat4 - nummat2; break;   // NUMMAT8
            case 28: v = nel2_; break;    // NEL2
            case 29: v = nummat2; break;  // NUMMAT2
            case 30: v = nv1d_; break;    // NV1D
            case 31: v = nel4_; break;    // NEL4
            case 32: v = nummat4; break;  // NUMMAT4
            case 33: v = nel4_ > 0 ? kShellPlotVars : 0; break;  // NV2D
            case 27: v = 7 + neiph_; break;  // NV3D = 7 + NEIPH
            case 34: v = neiph_; break;   // NEIPH
            case 36: v = -10003; break;   // MAXINT: element deletion flags
            case 39: v = 16 + numnp_ + nel8_ + nel2_ + nel4_ + 3 * static_cast<std::int64_t>(nmmat_); break;  // NARBS
            case 43: case 44: case 45: case 46: v = 1000; break;  // IOSHL
            case 51: v = nmmat_; break;   // NMMAT
            case 63: v = nif_; break;     // IMPACT-3D: sliding interfaces in the globals
            default: v = 0;
        }
        if (k == 13) put_text(b, "R960", static_cast<std::size_t>(ws));
        else if (k == 14) put_real(b, ws, 960.0);
        else put_int(b, ws, v);
    }
}

void PlotWriter::write_state(const PlotState& s) {
    if (!root_written_) throw std::logic_error("PlotWriter::write_state: database not open");
    const std::size_t nm = static_cast<std::size_t>(nmmat_);
    const std::size_t nn = static_cast<std::size_t>(numnp_);
    const std::size_t ne = static_cast<std::size_t>(nel8_);
    check_size(s.mat_internal_energy, nm, "mat_internal_energy", true);
    check_size(s.mat_kinetic_energy, nm, "mat_kinetic_energy", true);
    check_size(s.mat_velocity, 3 * nm, "mat_velocity", true);
    check_size(s.mat_mass, nm, "mat_mass", true);
    check_size(s.mat_hourglass_energy, nm, "mat_hourglass_energy", true);
    check_size(s.rigid_wall_forces, static_cast<std::size_t>(nrw_), "rigid_wall_forces", true);
    check_size(s.interface_forces, 3 * static_cast<std::size_t>(nif_), "interface_forces", true);
    check_size(s.coords, 3 * nn, "coords", true);
    check_size(s.vel, 3 * nn, "vel", true);
    check_size(s.acc, 3 * nn, "acc", true);
    check_size(s.stress, 6 * ne, "stress", true);
    check_size(s.eps, ne, "eps", true);
    check_size(s.history, static_cast<std::size_t>(neiph_) * ne, "history", true);
    check_size(s.alive, ne, "alive", true);
    const std::size_t ns = static_cast<std::size_t>(nel4_);
    check_size(s.shell_vars, kShellPlotVars * ns, "shell_vars", true);
    check_size(s.shell_alive, ns, "shell_alive", true);
    const std::size_t nb = static_cast<std::size_t>(nel2_);
    check_size(s.beam_vars, static_cast<std::size_t>(nv1d_) * nb, "beam_vars", true);
    check_size(s.beam_alive, nb, "beam_alive", true);

    const int ws = ws_;
    std::vector<char> b;
    b.reserve(static_cast<std::size_t>((state_words_ + 1) * ws));
    auto put_vec = [&](const std::vector<double>& v, std::size_t n) {
        if (v.empty())
            for (std::size_t k = 0; k < n; ++k) put_real(b, ws, 0.0);
        else
            for (double x : v) put_real(b, ws, x);
    };
    put_real(b, ws, s.time);
    put_real(b, ws, s.kinetic_energy);
    put_real(b, ws, s.internal_energy);
    put_real(b, ws, s.total_energy);
    for (double v : s.velocity) put_real(b, ws, v);
    put_vec(s.mat_internal_energy, nm);
    put_vec(s.mat_kinetic_energy, nm);
    put_vec(s.mat_velocity, 3 * nm);
    put_vec(s.mat_mass, nm);
    put_vec(s.mat_hourglass_energy, nm);
    put_vec(s.rigid_wall_forces, static_cast<std::size_t>(nrw_));
    put_vec(s.interface_forces, 3 * static_cast<std::size_t>(nif_));
    if (s.coords.empty()) put_vec(x0_, 3 * nn);
    else put_vec(s.coords, 3 * nn);
    put_vec(s.vel, 3 * nn);
    put_vec(s.acc, 3 * nn);
    for (std::size_t e = 0; e < ne; ++e) {
        for (int k = 0; k < 6; ++k) put_real(b, ws, s.stress.empty() ? 0.0 : s.stress[6 * e + k]);
        put_real(b, ws, s.eps.empty() ? 0.0 : s.eps[e]);
        for (int h = 0; h < neiph_; ++h)
            put_real(b, ws, s.history.empty() ? 0.0 : s.history[static_cast<std::size_t>(neiph_) * e + h]);
    }
    put_vec(s.beam_vars, static_cast<std::size_t>(nv1d_) * nb);
    put_vec(s.shell_vars, kShellPlotVars * ns);
    // deletion flags: solids, (thick shells,) shells, beams
    for (std::size_t e = 0; e < ne; ++e) put_real(b, ws, (s.alive.empty() || s.alive[e]) ? 1.0 : 0.0);
    for (std::size_t e = 0; e < ns; ++e) put_real(b, ws, (s.shell_alive.empty() || s.shell_alive[e]) ? 1.0 : 0.0);
    for (std::size_t e = 0; e < nb; ++e) put_real(b, ws, (s.beam_alive.empty() || s.beam_alive[e]) ? 1.0 : 0.0);
    if (static_cast<std::int64_t>(b.size()) != state_words_ * ws)
        throw std::logic_error("PlotWriter: internal error: state size mismatch");

    const bool fits = fd_ >= 0 && (marker_pos_ / ws + state_words_ + 1 <= limit_words_);
    if (fits) append_to_member(b);
    else start_member(b);
    ++states_written_;
}

// New member: written completely under a temporary name, fsync'ed, then renamed into place, so
// that a reader never sees a partly written member.
void PlotWriter::start_member(const std::vector<char>& buf) {
    sync();  // the member before it durable first: a machine crash leaves no gap
    const int m = members_ + 1;
    const std::string name = member_name(root_, m);
    const std::string tmp = name + ".tmp";
    const int fd = ::open(tmp.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) io_fail("open of", tmp, errno);
    try {
        std::vector<char> all(buf);
        put_real(all, ws_, kEndMarker);
        pwrite_all(fd, all.data(), all.size(), 0, tmp);
        fsync_or_throw(fd, tmp);
        ++syncs_;
        if (::rename(tmp.c_str(), name.c_str()) != 0) io_fail("rename to " + name + " of", tmp, errno);
    } catch (...) {
        ::close(fd);
        ::unlink(tmp.c_str());
        throw;
    }
    fsync_dir_best_effort(parent_dir(name));
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
    members_ = m;
    states_in_member_ = 1;
    unsynced_ = false;
    last_sync_ns_ = steady_ns();
    marker_pos_ = static_cast<std::int64_t>(buf.size());
}

// Append to the current member: body + new marker after the old marker first, then the time word
// over the old marker (the commit).  Until the commit the old marker ends the member.
void PlotWriter::append_to_member(const std::vector<char>& buf) {
    const std::string name = member_name(root_, members_);
    const std::int64_t off = marker_pos_;
    std::vector<char> tail(buf.begin() + ws_, buf.end());
    put_real(tail, ws_, kEndMarker);
    const bool durable = sync_interval_ <= 0 || double(steady_ns() - last_sync_ns_) >= 1e9 * sync_interval_;
    try {
        pwrite_all(fd_, tail.data(), tail.size(), off + ws_, name);
        if (durable) fsync_or_throw(fd_, name);
    } catch (...) {
        if (::ftruncate(fd_, static_cast<off_t>(off + ws_)) == 0) (void)::fsync(fd_);
        throw;
    }
    try {
        pwrite_all(fd_, buf.data(), static_cast<std::size_t>(ws_), off, name);
        if (durable) fsync_or_throw(fd_, name);
    } catch (...) {
        std::vector<char> mk;
        put_real(mk, ws_, kEndMarker);
        (void)::pwrite(fd_, mk.data(), mk.size(), static_cast<off_t>(off));
        if (::ftruncate(fd_, static_cast<off_t>(off + ws_)) == 0) (void)::fsync(fd_);
        throw;
    }
    marker_pos_ += static_cast<std::int64_t>(buf.size());
    ++states_in_member_;
    if (durable) {
        syncs_ += 2;
        last_sync_ns_ = steady_ns();
    }
    unsynced_ = !durable;
}

// =============================================================================================
// PlotReader

PlotControl PlotReader::read_control(const std::string& root_path) {
    const std::int64_t size = file_size_or(root_path, -1);
    if (size < 0) throw std::runtime_error("plot database " + root_path + ": cannot open: no such regular file");
    const std::vector<char> head = read_range(root_path, 0, std::min<std::int64_t>(size, 64 * 8), "control words");
    return parse_control(head, root_path);
}

namespace {

// Digit k (0 = units) of a non-negative control word (IT, IDTDT are digit flags).
int digit(std::int64_t v, int k) {
    if (v < 0) return 0;
    for (; k > 0; --k) v /= 10;
    return static_cast<int>(v % 10);
}

constexpr std::int64_t kFemzipMarker = 76893465;  // NMMAT of a femzip-compressed d3plot
constexpr int kRigidPartType = 20;                // LS-DYNA material type of rigid parts

// Node words of one state, per node, in file order.
struct NodeWords {
    int coords = 0, temps = 0, flux = 0, mass_scaling = 0, temp_rate = 0, residual = 0, vel = 0, acc = 0;
    int total() const { return coords + temps + flux + mass_scaling + temp_rate + residual + vel + acc; }
};

NodeWords node_words(const PlotControl& c) {
    NodeWords w;
    w.coords = 3 * static_cast<int>(c.iu);
    const int t = digit(c.it, 0);
    w.temps = t == 3 ? 3 : (t >= 1 ? 1 : 0);
    w.flux = t >= 2 ? 3 : 0;
    w.mass_scaling = digit(c.it, 1) == 1 ? 1 : 0;
    w.temp_rate = digit(c.idtdt, 0) == 1 ? 1 : 0;
    w.residual = digit(c.idtdt, 1) == 1 ? 6 : 0;  // residual forces and moments
    w.vel = 3 * static_cast<int>(c.iv);
    w.acc = 3 * static_cast<int>(c.ia);
    return w;
}

// Shell/thick-shell integration points through the thickness: MAXINT without the MDLOPT part
// (LS-DYNA's default of 3 when it is 0).
int shell_layers(const PlotControl& c) {
    std::int64_t m = c.maxint < 0 ? -c.maxint : c.maxint;
    m %= 10000;
    return m == 0 ? 3 : static_cast<int>(m);
}

// Record layouts from the control words; refuses element records whose length (NV3D, NV3DT,
// NV1D, NV2D) does not split into the values the flags announce.  The counts are at most
// 2^31 - 1 (PlotReader::open checked them); the sums and products are formed in 64 bits and
// refused where they would not fit the layout's int offsets.
PlotLayout make_layout(const PlotControl& c, const std::string& f) {
    PlotLayout L;
    auto refuse = [&](const std::string& what) {
        throw std::runtime_error("plot database " + f + ": unsupported d3plot content: " + what);
    };
    auto offset = [&](std::int64_t v, const char* what) {
        if (v > std::numeric_limits<std::int32_t>::max())
            refuse(std::string(what) + " of " + std::to_string(v) + " words");
        return static_cast<int>(v);
    };
    // solids: 6 stresses + EPS + NEIPH (as VTK: whatever IOSHL says), at 1 or 8 points
    L.solid_history = offset(c.neiph, "solid history values (NEIPH)");
    L.solid_point_words = offset(7 + c.neiph, "solid integration points (7 + NEIPH)");
    if (c.nel8 != 0) {
        if (c.nv3d == L.solid_point_words) L.solid_points = 1;
        else if (c.nv3d == 8 * static_cast<std::int64_t>(L.solid_point_words)) L.solid_points = 8;
        else refuse("NV3D " + std::to_string(c.nv3d) + " is neither 7 + NEIPH (" + std::to_string(L.solid_point_words) +
                    ") nor 8 integration points of it");
    }
    // shells and thick shells share the layer layout
    L.layers = shell_layers(c);
    std::int64_t w = 0;
    if (c.ioshl[0] == 1000) { L.layer_stress = static_cast<int>(w); w += 6; }
    if (c.ioshl[1] == 1000) { L.layer_eps = static_cast<int>(w); w += 1; }
    if (c.neips > 0) { L.layer_history = static_cast<int>(w); w += c.neips; }
    L.layer_words = offset(w, "shell layers (NEIPS)");
    const std::int64_t layer_total = static_cast<std::int64_t>(L.layers) * w;
    offset(layer_total + 32, "shell layers (MAXINT x NEIPS) and their resultants");
    if (c.nel4 != 0 && c.nv2d != 0) {
        std::int64_t at = layer_total;
        const bool forces = c.ioshl[2] == 1000, extra = c.ioshl[3] == 1000;
        if (forces) { L.shell_forces = static_cast<int>(at); at += 8; }
        if (extra) { L.shell_thickness = static_cast<int>(at); at += 3; }
        std::int64_t rest = c.nv2d - at - (extra ? 1 : 0);
        if (digit(c.idtdt, 2) == 1) rest -= 6 * L.layers;  // plastic strain tensor per layer
        if (digit(c.idtdt, 3) == 1) rest -= 6;             // thermal strain tensor
        if (rest == 12) { L.shell_strain = static_cast<int>(at); at += 12; }
        else if (rest != 0)
            refuse("NV2D " + std::to_string(c.nv2d) + " does not split into " + std::to_string(L.layers) +
                   " layers of " + std::to_string(w) + " words, resultants, extra words and strains");
        if (extra) L.shell_internal_energy = static_cast<int>(at);
    }
    if (c.nelt != 0 && c.nv3dt != 0) {
        const std::int64_t rest = c.nv3dt - layer_total;
        if (rest == 12) L.tshell_strain = static_cast<int>(layer_total);
        else if (rest != 0)
            refuse("NV3DT " + std::to_string(c.nv3dt) + " does not split into " + std::to_string(L.layers) +
                   " layers of " + std::to_string(w) + " words and strains");
    }
    if (c.nel2 != 0 && c.nv1d != 0) {
        L.beam_history = static_cast<int>(c.neipb);
        const std::int64_t num = c.nv1d - 6 - 3 * c.neipb, den = 5 + c.neipb;
        if (num < 0 || num % den != 0)
            refuse("NV1D " + std::to_string(c.nv1d) + " is not 6 resultants plus integration points of " +
                   std::to_string(den) + " words (NEIPB " + std::to_string(c.neipb) + ")");
        L.beam_points = static_cast<int>(num / den);
    }
    return L;
}

// A control word that counts something: checked, in 64 bits, against what the family can hold
// (each node, element, part, state word or extra word takes at least one word of it).
void check_count(std::int64_t v, const char* name, const std::string& f, std::int64_t family_words) {
    if (v < 0 || v > std::numeric_limits<std::int32_t>::max() || v > family_words)
        throw std::runtime_error("plot database " + f + ": implausible control word " + name + " = " +
                                 std::to_string(v) + " (the family holds " + std::to_string(family_words) +
                                 " words)");
}

// What this reader supports: refuses (std::runtime_error naming the control word) what it does
// not read, and counts the family cannot hold.
void check_supported(const PlotControl& c, const std::string& f, std::int64_t family_words) {
    const int ws = c.word_size;
    auto bad_count = [&](std::int64_t v, const char* name) { check_count(v, name, f, family_words); };
    if (c.nmmat == kFemzipMarker)
        throw std::runtime_error("plot database " + f + ": femzip-compressed d3plot (NMMAT " +
                                 std::to_string(kFemzipMarker) +
                                 " marks it): this reader cannot decompress it; uncompress it first (femunzip)");
    const std::int64_t ft = c.filetype > 1000 ? c.filetype - 1000 : c.filetype;
    if (ft != 1) unsupported(f, "FILETYPE " + std::to_string(c.filetype) + " is not a d3plot (1)");
    if (c.filetype > 1000 && ws == 4) unsupported(f, "64-bit user ids in a 4-byte file (FILETYPE > 1000)");
    if (c.ndim != 4 && c.ndim != 5)
        unsupported(f, "NDIM " + std::to_string(c.ndim) + " (only 4, and 5 with the material-type section)");
    if (c.nel8 < 0) unsupported(f, "10-node tetrahedra (NEL8 < 0)");
    bad_count(c.numnp, "NUMNP");
    bad_count(c.nel8, "NEL8");
    bad_count(c.nelt, "NELT");
    bad_count(c.nel2, "NEL2");
    bad_count(c.nel4, "NEL4");
    bad_count(c.nglbv, "NGLBV");
    bad_count(c.nummat8, "NUMMAT8");
    bad_count(c.nummatt, "NUMMATT");
    bad_count(c.nummat2, "NUMMAT2");
    bad_count(c.nummat4, "NUMMAT4");
    bad_count(c.nmmat, "NMMAT");
    bad_count(c.narbs, "NARBS");
    bad_count(c.neiph, "NEIPH");
    bad_count(c.neips, "NEIPS");
    bad_count(c.nv3d, "NV3D");
    bad_count(c.nv3dt, "NV3DT");
    bad_count(c.nv1d, "NV1D");
    bad_count(c.nv2d, "NV2D");
    bad_count(c.extra, "EXTRA");
    if (c.maxint < -std::numeric_limits<std::int32_t>::max()) bad_count(c.maxint, "MAXINT");
    if (c.nel48 != 0) unsupported(f, std::to_string(c.nel48) + " 8-node shells (NEL48)");
    if (c.nmsph != 0 || c.ngpsph != 0) unsupported(f, "SPH data (NMSPH/NGPSPH)");
    if (c.ialemat != 0 || c.numfluid != 0) unsupported(f, "ALE data (IALEMAT/NUMFLUID)");
    if (c.npefg != 0) unsupported(f, "airbag particle data (NPEFG)");
    if (c.ncfdv1 != 0 || c.ncfdv2 != 0) unsupported(f, "CFD node data (NCFDV1/NCFDV2)");
    if (c.nadapt != 0) unsupported(f, "adaptive meshing (NADAPT)");
    if (c.it < 0 || digit(c.it, 0) > 3 || c.it >= 100) unsupported(f, "IT " + std::to_string(c.it) + " (only 0-3, +10 mass scaling)");
    if (c.idtdt < 0) unsupported(f, "IDTDT " + std::to_string(c.idtdt));
    for (std::int64_t flag : {c.iu, c.iv, c.ia})
        if (flag != 0 && flag != 1) throw std::runtime_error("plot database " + f + ": implausible IU/IV/IA flag " +
                                                             std::to_string(flag));

}

// The EXTRA control words after the 64 (NT3D, NEIPB, the higher-order solid counts).
void read_extra_control_words(Cursor& cur, PlotControl& c, const std::string& f, std::int64_t family_words) {
    auto bad_count = [&](std::int64_t v, const char* name) { check_count(v, name, f, family_words); };
    cur.need_words(c.extra, "the EXTRA control words");
    std::int64_t x[16] = {};
    for (std::int64_t k = 0; k < c.extra; ++k) {
        const std::int64_t v = cur.i("EXTRA control word");
        if (k < 16) x[k] = v;
    }
    c.nel20 = x[0]; c.nt3d = x[1]; c.nel27 = x[2]; c.neipb = x[3]; c.nel21p = x[4]; c.nel15t = x[5];
    c.soleng = x[6]; c.nel20t = x[7]; c.nel40p = x[8]; c.nel64 = x[9]; c.quadr = x[10]; c.cubic = x[11];
    c.tsheng = x[12];
    bad_count(c.nt3d, "NT3D");
    bad_count(c.neipb, "NEIPB");
    const std::pair<std::int64_t, const char*> higher[] = {
        {c.nel20, "20-node solids (NEL20)"}, {c.nel27, "27-node solids (NEL27)"},
        {c.nel21p, "21-node pentahedra (NEL21P)"}, {c.nel15t, "15-node tetrahedra (NEL15T)"},
        {c.nel20t, "20-node tetrahedra (NEL20T)"}, {c.nel40p, "40-node pentahedra (NEL40P)"},
        {c.nel64, "64-node solids (NEL64)"}};
    for (const auto& [n, what] : higher)
        if (n != 0) unsupported(f, std::to_string(n) + " " + what);
}

// The material-type section (NDIM 5): the parts' material types; returns NUMRBE (rigid shells,
// which have no state data).
std::int64_t read_part_types(Cursor& cur, const PlotControl& c, std::int64_t nparts, PlotGeometry& g) {
    const int ws = c.word_size;
    const std::int64_t numrbe = cur.i("NUMRBE");
    const std::int64_t nm = cur.i("material-type section NMMAT");
    if (numrbe < 0 || numrbe > c.nel4 || nm != nparts) {
        cur.seek(cur.pos() - 2 * ws);
        cur.fail("NUMRBE in 0.." + std::to_string(c.nel4) + " and NMMAT " + std::to_string(nparts) +
                     " (material-type section), found " + std::to_string(numrbe) + " and " + std::to_string(nm),
                 -1);
    }
    cur.need_words(nparts, "the material types of " + std::to_string(nparts) + " parts");
    g.part_types.resize(static_cast<std::size_t>(nparts));
    for (auto& t : g.part_types) t = static_cast<int>(std::clamp<std::int64_t>(cur.i("material type"), -1, 1000000));
    return numrbe;
}

// One element block: per element `nodes` node words (the first `kept` of them checked and kept;
// beams: the orientation node and two unused words follow), then the material number.
void read_element_block(Cursor& cur, std::int64_t count, int nodes, int kept, const char* what, std::int64_t numnp,
                        std::int64_t nparts, std::vector<int>& node_out, std::vector<int>& mat_out) {
    const std::string& f = cur.file();
    const int ws = cur.word_size();
    cur.need_words(checked_mul(nodes + 1, count, f), "connectivity of " + std::to_string(count) + " " + what);
    node_out.resize(static_cast<std::size_t>(kept * count));
    mat_out.resize(static_cast<std::size_t>(count));
    for (std::int64_t e = 0; e < count; ++e) {
        for (int k = 0; k < nodes; ++k) {
            const std::int64_t n = cur.i("node number");
            if (k >= kept) continue;
            if (n < 1 || n > numnp) {
                cur.seek(cur.pos() - ws);
                cur.fail("a node number in 1.." + std::to_string(numnp) + " for " + what + " " +
                             std::to_string(e + 1) + ", found " + std::to_string(n),
                         -1);
            }
            node_out[static_cast<std::size_t>(kept * e + k)] = static_cast<int>(n - 1);
        }
        const std::int64_t m = cur.i("material number");
        if (m < 1 || m > nparts) {
            cur.seek(cur.pos() - ws);
            cur.fail("a material number in 1.." + std::to_string(nparts) + " for " + what + " " +
                         std::to_string(e + 1) + ", found " + std::to_string(m),
                     -1);
        }
        mat_out[static_cast<std::size_t>(e)] = static_cast<int>(m);
    }
}

// After the per-part globals: NUMRW rigid-wall words, then 3 words per sliding interface
// (control word 63, ours); a word 63 that does not fit is not ours: all are walls. LS-DYNA from
// VERSION 971 on writes 4 words per wall: the force, then its x y z position.
void count_walls_and_interfaces(const PlotControl& c, std::int64_t nparts, PlotGeometry& g) {
    const std::int64_t extra_globals = c.nglbv - 6 - 7 * nparts;
    const std::int64_t nif = (c.nintf > 0 && c.nintf <= 100000 && c.nintf <= extra_globals / 3) ? c.nintf : 0;
    g.num_interfaces = static_cast<int>(nif);
    const std::int64_t wall_words = extra_globals - 3 * nif;
    g.num_rigid_walls = extra_globals <= 0 ? 0 : static_cast<int>(c.version >= 971.0 && nif == 0 ? wall_words / 4 : wall_words);
}

void sequential_ids(std::vector<int>& ids, std::int64_t n) {
    ids.resize(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k) ids[static_cast<std::size_t>(k)] = static_cast<int>(k + 1);
}

// The NARBS user-id section (nodes, solids, beams, shells, thick shells, parts), or ids 1..n.
void read_user_ids(Cursor& cur, const PlotControl& c, std::int64_t nparts, PlotGeometry& g) {
    const std::string& f = cur.file();
    const int ws = c.word_size;
    const std::int64_t numnp = c.numnp, nel8 = c.nel8;
    if (c.narbs > 0) {
        cur.need_words(c.narbs, "the user-id (NARBS) section of " + std::to_string(c.narbs) + " words");
        const std::int64_t start = cur.pos();
        const std::int64_t nsort = cur.i("NSORT");
        const std::int64_t hdr = nsort < 0 ? 16 : 10;
        std::int64_t ids = checked_add(hdr, checked_add(numnp, nel8, f), f);
        ids = checked_add(ids, c.nel2 + c.nel4 + c.nelt, f);
        if (ids > c.narbs)
            cur.fail("a user-id section of at least " + std::to_string(ids) + " words (NARBS = " +
                         std::to_string(c.narbs) + ")",
                     -1);
        cur.seek(start + hdr * ws);
        auto to_int = [&](std::int64_t v) {
            return static_cast<int>(std::clamp<std::int64_t>(v, std::numeric_limits<int>::min(),
                                                             std::numeric_limits<int>::max()));
        };
        auto read_ids = [&](std::vector<int>& out, std::int64_t n, const char* what) {
            out.resize(static_cast<std::size_t>(n));
            for (auto& id : out) id = to_int(cur.i(what));
        };
        read_ids(g.node_user_ids, numnp, "user node id");
        read_ids(g.hex_user_ids, nel8, "user solid id");
        read_ids(g.beam_user_ids, c.nel2, "user beam id");
        read_ids(g.shell_user_ids, c.nel4, "user shell id");
        read_ids(g.tshell_user_ids, c.nelt, "user thick shell id");
        if (nsort < 0 && ids + 3 * nparts <= c.narbs) {
            cur.skip_words(nparts, "NORDER");
            read_ids(g.part_user_ids, nparts, "user part id");
        }
        cur.seek(start + c.narbs * ws);
    } else {
        sequential_ids(g.node_user_ids, numnp);
        sequential_ids(g.hex_user_ids, nel8);
        sequential_ids(g.beam_user_ids, c.nel2);
        sequential_ids(g.shell_user_ids, c.nel4);
        sequential_ids(g.tshell_user_ids, c.nelt);
    }
    if (g.part_user_ids.empty() && nparts <= cur.remaining() + 1000000) sequential_ids(g.part_user_ids, nparts);
}

// The title records after the end marker: part titles by part id (90001), the model title
// (90000); d3prop lines skipped.
void read_title_records(Cursor& cur, std::int64_t nparts, PlotGeometry& g) {
    const std::string& f = cur.file();
    const int ws = cur.word_size();
    if (cur.has(ws) && cur.r("end marker") == kEndMarker) {
        while (cur.has(ws)) {
            const std::int64_t at = cur.pos();
            const std::int64_t code = cur.i("title record code");
            if (code == 90001 || code == 90002 || code == 90020) {
                const std::int64_t nprop = cur.i("number of title records");
                if (nprop < 0 || nprop > cur.remaining()) {
                    cur.seek(at + ws);
                    cur.fail("a plausible number of title records, found " + std::to_string(nprop), -1);
                }
                cur.need(checked_mul(nprop, ws + kTitleRecordBytes, f), std::to_string(nprop) + " title records");
                std::vector<std::pair<std::int64_t, std::string>> titles;
                for (std::int64_t p = 0; p < nprop; ++p) {
                    const std::int64_t id = cur.i("part id");
                    titles.emplace_back(id, trim_right(cur.text(kTitleRecordBytes, "part title")));
                }
                if (code == 90001) {
                    // by user part id; titles of ids that are no part are dropped
                    g.part_titles.assign(static_cast<std::size_t>(nparts), std::string());
                    for (std::size_t k = 0; k < titles.size(); ++k) {
                        const auto it = std::find(g.part_user_ids.begin(), g.part_user_ids.end(), titles[k].first);
                        if (it != g.part_user_ids.end()) g.part_titles[static_cast<std::size_t>(it - g.part_user_ids.begin())] = titles[k].second;
                        else if (static_cast<std::int64_t>(titles.size()) == nparts) g.part_titles[k] = titles[k].second;
                    }
                }
            } else if (code == 90000) {
                g.title = trim_right(cur.text(kTitleRecordBytes, "model title record"));
            } else if (code == 90100) {
                const std::int64_t nline = cur.i("number of d3prop lines");
                if (nline < 0 || nline > cur.remaining() / 80) break;
                cur.need(nline * 80, "d3prop keyword lines");
                cur.seek(cur.pos() + nline * 80);
            } else {
                break;  // end marker, padding, ...: done
            }
        }
    }

}

// The words of one state.
std::int64_t state_words(const PlotControl& c, std::int64_t rigid_shells, const std::string& f) {
    const std::int64_t numnp = c.numnp, nel8 = c.nel8;
    const NodeWords nw = node_words(c);
    std::int64_t words = checked_add(1 + c.nglbv, checked_mul(numnp, nw.total(), f), f);
    words = checked_add(words, checked_mul(nel8, c.nt3d, f), f);
    words = checked_add(words, checked_mul(nel8, c.nv3d, f), f);
    words = checked_add(words, checked_mul(c.nelt, c.nv3dt, f), f);
    words = checked_add(words, checked_mul(c.nel2, c.nv1d, f), f);
    words = checked_add(words, checked_mul(c.nel4 - rigid_shells, c.nv2d, f), f);
    if (c.maxint < -10000) words = checked_add(words, nel8 + c.nelt + c.nel4 + c.nel2, f);
    else if (c.maxint < 0) words = checked_add(words, numnp, f);
    return words;
}

// The state's first word (its time) at p.
double time_word(const char* p, int ws, bool swap) {
    char tmp[8];
    std::memcpy(tmp, p, ws);
    if (swap) std::reverse(tmp, tmp + ws);
    if (ws == 4) {
        float x;
        std::memcpy(&x, tmp, 4);
        return static_cast<double>(x);
    }
    double x;
    std::memcpy(&x, tmp, 8);
    return x;
}

}  // namespace

void PlotReader::open(const std::string& root_path) {
    root_ = root_path;
    ctl_ = PlotControl{};
    geom_ = PlotGeometry{};
    layout_ = PlotLayout{};
    rigid_shells_ = 0;
    states_.clear();
    state_bytes_ = 0;
    static_end_ = 0;
    num_members_ = 0;

    const std::vector<char> d = read_whole_file(root_path);
    const std::string& f = root_path;
    PlotControl c = parse_control(d, f);
    const int ws = c.word_size;
    const bool swap = c.byte_swapped != kHostBig;
    // Every count of the header is untrusted: it is checked against what the family can hold
    // before anything is sized or added from it.
    const std::int64_t family_words = family_bytes(root_path, d.size()) / ws;
    check_supported(c, f, family_words);

    Cursor cur(d.data(), static_cast<std::int64_t>(d.size()), f, 0, ws, swap);
    cur.seek(64 * ws);
    if (c.extra > 0) read_extra_control_words(cur, c, f, family_words);
    const std::int64_t nparts = c.nmmat > 0 ? c.nmmat : c.nummat8 + c.nummatt + c.nummat2 + c.nummat4;
    // The part count sizes per-part arrays and loops here and in POST-IMPACT, but nothing in
    // the root file has to follow from it: checked against the words the whole family holds
    // (each part has words in every state), so a corrupt count cannot ask for gigabytes.
    if (nparts > family_words)
        throw std::runtime_error("plot database " + f + ": implausible control words: " + std::to_string(nparts) +
                                 " parts (NMMAT/NUMMAT8) in a family of " + std::to_string(family_words) + " words");
    const PlotLayout layout = make_layout(c, f);
    const std::int64_t numnp = c.numnp, nel8 = c.nel8;

    PlotGeometry g;
    g.title = c.title;
    // ---- material-type section (NDIM 5), geometry, user ids, titles
    if (c.ndim == 5) rigid_shells_ = read_part_types(cur, c, nparts, g);
    cur.need_words(checked_mul(3, numnp, f), "initial coordinates of " + std::to_string(numnp) + " nodes");
    g.x0.resize(static_cast<std::size_t>(3 * numnp));
    for (auto& x : g.x0) x = cur.r("coordinate");
    read_element_block(cur, nel8, 8, 8, "solid", numnp, nparts, g.hex_nodes, g.hex_material);
    read_element_block(cur, c.nelt, 8, 8, "thick shell", numnp, nparts, g.tshell_nodes, g.tshell_material);
    read_element_block(cur, c.nel2, 5, 2, "beam", numnp, nparts, g.beam_nodes, g.beam_material);
    read_element_block(cur, c.nel4, 4, 4, "shell", numnp, nparts, g.shell_nodes, g.shell_material);
    if (rigid_shells_ > 0) {
        std::int64_t rigid = 0;
        for (int m : g.shell_material)
            if (g.part_types[static_cast<std::size_t>(m - 1)] == kRigidPartType) ++rigid;
        if (rigid != rigid_shells_)
            unsupported(f, "NUMRBE " + std::to_string(rigid_shells_) + " rigid shells, but " + std::to_string(rigid) +
                               " shells belong to parts of material type 20");
    }
    g.num_materials = static_cast<int>(nparts);
    count_walls_and_interfaces(c, nparts, g);
    read_user_ids(cur, c, nparts, g);
    static_end_ = cur.pos();
    read_title_records(cur, nparts, g);

    // ---- state size and family scan
    state_bytes_ = checked_mul(state_words(c, rigid_shells_, f), ws, f);
    ctl_ = c;
    geom_ = std::move(g);
    layout_ = layout;
    // Root file: states may follow the static part directly (old layouts); a marker ends them.
    {
        std::int64_t pos = static_end_;
        const std::int64_t size = static_cast<std::int64_t>(d.size());
        while (pos + ws <= size) {
            const double t = time_word(d.data() + pos, ws, swap);
            if (t == kEndMarker || state_bytes_ > size - pos) break;
            states_.push_back({0, pos, t});
            pos += state_bytes_;
        }
    }
    for (int m = 1;; ++m) {
        const std::string name = PlotWriter::member_name(root_, m);
        const std::int64_t size = file_size_or(name, -1);
        if (size < 0) break;
        num_members_ = m;
        std::ifstream in(name, std::ios::binary);
        if (!in) throw std::runtime_error("plot database " + name + ": cannot open");
        std::int64_t pos = 0;
        bool partial = false;
        while (pos + ws <= size) {
            char w[8];
            if (!in.seekg(pos) || !in.read(w, ws)) {
                std::ostringstream os;
                os << "plot database " << name << ": read error at byte offset " << pos;
                throw std::runtime_error(os.str());
            }
            const double t = time_word(w, ws, swap);
            if (t == kEndMarker) break;
            if (state_bytes_ > size - pos) {
                partial = true;
                break;
            }
            states_.push_back({m, pos, t});
            pos += state_bytes_;
        }
        if (partial && file_size_or(PlotWriter::member_name(root_, m + 1), -1) >= 0) {
            std::ostringstream os;
            os << "plot database " << name << ": truncated at byte offset " << pos
               << ": expected a complete state of " << state_bytes_ << " bytes, but the file has " << size
               << " bytes and is not the last family member";
            throw std::runtime_error(os.str());
        }
        // (a partial trailing state in the last member is what a killed run leaves: ignored)
    }
}

double PlotReader::time(int i) const {
    if (i < 0 || i >= num_states()) throw std::out_of_range("PlotReader::time: no state " + std::to_string(i));
    return states_[static_cast<std::size_t>(i)].time;
}

PlotState PlotReader::state(int i) const {
    if (i < 0 || i >= num_states()) throw std::out_of_range("PlotReader::state: no state " + std::to_string(i));
    const StateLoc& loc = states_[static_cast<std::size_t>(i)];
    const std::string name = PlotWriter::member_name(root_, loc.member);
    const std::vector<char> buf = read_range(name, loc.offset, state_bytes_, "state " + std::to_string(i));
    const PlotControl& c = ctl_;
    const int ws = c.word_size;
    Cursor cur(buf.data(), static_cast<std::int64_t>(buf.size()), name, loc.offset, ws, c.byte_swapped != kHostBig);

    PlotState s;
    s.time = cur.r("time");
    std::vector<double> glob(static_cast<std::size_t>(c.nglbv));
    for (auto& v : glob) v = cur.r("global");
    if (glob.size() >= 1) s.kinetic_energy = glob[0];
    if (glob.size() >= 2) s.internal_energy = glob[1];
    if (glob.size() >= 3) s.total_energy = glob[2];
    for (std::size_t k = 0; k < 3; ++k)
        if (glob.size() >= 4 + k) s.velocity[k] = glob[3 + k];
    const std::size_t nm = static_cast<std::size_t>(geom_.num_materials);
    if (glob.size() >= 6 + 7 * nm) {
        auto it = glob.begin() + 6;
        auto take = [&](std::vector<double>& v, std::size_t n) {
            v.assign(it, it + static_cast<std::ptrdiff_t>(n));
            it += static_cast<std::ptrdiff_t>(n);
        };
        take(s.mat_internal_energy, nm);
        take(s.mat_kinetic_energy, nm);
        take(s.mat_velocity, 3 * nm);
        take(s.mat_mass, nm);
        take(s.mat_hourglass_energy, nm);
        const std::size_t nif = 3 * static_cast<std::size_t>(geom_.num_interfaces);
        s.rigid_wall_forces.assign(it, glob.end() - static_cast<std::ptrdiff_t>(nif));
        if (c.version >= 971.0 && nif == 0) {  // force, x, y, z per wall: the forces
            std::vector<double> f(static_cast<std::size_t>(geom_.num_rigid_walls));
            for (std::size_t k = 0; k < f.size(); ++k) f[k] = s.rigid_wall_forces[4 * k];
            s.rigid_wall_forces = std::move(f);
        }
        s.interface_forces.assign(glob.end() - static_cast<std::ptrdiff_t>(nif), glob.end());
    }
    const std::size_t nn = static_cast<std::size_t>(c.numnp), ne = static_cast<std::size_t>(c.nel8);
    auto read_vec = [&](std::vector<double>& v, std::size_t n, const char* what) {
        v.resize(n);
        for (auto& x : v) x = cur.r(what);
    };
    // ---- nodes: coordinates, temperatures, flux, mass scaling, dT/dt, residuals, velocities, accelerations
    const NodeWords nw = node_words(c);
    if (nw.coords) read_vec(s.coords, 3 * nn, "current coordinates");
    if (nw.temps == 1) {
        read_vec(s.temperature, nn, "temperatures");
    } else if (nw.temps == 3) {  // IT 3: inner, middle, outer arrays (the manual): the middle one
        cur.skip_words(static_cast<std::int64_t>(nn), "inner-layer temperatures");
        read_vec(s.temperature, nn, "middle-layer temperatures");
        cur.skip_words(static_cast<std::int64_t>(nn), "outer-layer temperatures");
    }
    cur.skip_words(static_cast<std::int64_t>(nn) * (nw.flux + nw.mass_scaling + nw.temp_rate + nw.residual),
                   "heat flux, mass scaling, dT/dt and residual node values");
    if (nw.vel) read_vec(s.vel, 3 * nn, "velocities");
    if (nw.acc) read_vec(s.acc, 3 * nn, "accelerations");
    cur.skip_words(static_cast<std::int64_t>(ne) * c.nt3d, "thermal solid data (NT3D)");
    // ---- solids: stress and EPS (means over the integration points), raw records when longer
    const PlotLayout& L = layout_;
    s.stress.assign(6 * ne, 0.0);
    s.eps.assign(ne, 0.0);
    if (c.nv3d > 7) read_vec(s.solid_vars, ne * static_cast<std::size_t>(c.nv3d), "solid record");
    const std::size_t nh = static_cast<std::size_t>(L.solid_history);
    s.history.assign(nh * ne, 0.0);
    for (std::size_t e = 0; e < ne; ++e) {
        if (c.nv3d > 7) {
            const double* rec = &s.solid_vars[e * static_cast<std::size_t>(c.nv3d)];
            for (int p = 0; p < L.solid_points; ++p) {
                const double* v = rec + p * L.solid_point_words;
                for (int k = 0; k < 6; ++k) s.stress[6 * e + k] += v[k] / L.solid_points;
                s.eps[e] += v[6] / L.solid_points;
                // the extra history values (NEIPH) after the EPS, as means over the points
                for (std::size_t h = 0; h < nh; ++h) s.history[nh * e + h] += v[7 + h] / L.solid_points;
            }
        } else {
            for (int k = 0; k < 6; ++k) s.stress[6 * e + k] = cur.r("solid stress");
            s.eps[e] = cur.r("solid effective plastic strain");
        }
    }
    // ---- thick shells, beams, shells: raw records (rigid shells of NDIM 5: no data, zeros)
    read_vec(s.tshell_vars, static_cast<std::size_t>(c.nelt * c.nv3dt), "thick shell record");
    read_vec(s.beam_vars, static_cast<std::size_t>(c.nel2 * c.nv1d), "beam record");
    const std::size_t ns = static_cast<std::size_t>(c.nel4), nv2d = static_cast<std::size_t>(c.nv2d);
    s.shell_vars.assign(ns * nv2d, 0.0);
    for (std::size_t e = 0; e < ns && nv2d > 0; ++e) {
        if (rigid_shells_ > 0 &&
            geom_.part_types[static_cast<std::size_t>(geom_.shell_material[e] - 1)] == kRigidPartType)
            continue;
        for (std::size_t k = 0; k < nv2d; ++k) s.shell_vars[e * nv2d + k] = cur.r("shell record");
    }
    // ---- deletion flags: solids, thick shells, shells, beams (0.0 = deleted)
    auto read_alive = [&](std::vector<unsigned char>& a, std::size_t n) {
        a.resize(n);
        for (auto& x : a) x = cur.r("element deletion flag") != 0.0 ? 1 : 0;
    };
    s.alive.assign(ne, 1);
    if (c.maxint < -10000) {
        read_alive(s.alive, ne);
        read_alive(s.tshell_alive, static_cast<std::size_t>(c.nelt));
        read_alive(s.shell_alive, ns);
        read_alive(s.beam_alive, static_cast<std::size_t>(c.nel2));
    } else if (c.maxint < 0) {
        read_alive(s.node_alive, nn);
    }
    return s;
}

}  // namespace impact3d
