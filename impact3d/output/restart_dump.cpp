#include "impact3d/output/restart_dump.h"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace impact3d {

namespace {

// CRC-32 of any length (zlib's crc32 takes 32-bit lengths: fold in chunks).
std::uint32_t crc32_of(const char* p, std::size_t n) {
  uLong c = crc32(0L, Z_NULL, 0);
  while (n > 0) {
    const std::size_t k = std::min<std::size_t>(n, std::size_t(1) << 30);
    c = crc32(c, reinterpret_cast<const Bytef*>(p), static_cast<uInt>(k));
    p += k;
    n -= k;
  }
  return static_cast<std::uint32_t>(c);
}

constexpr char kMagic[16] = {'I', 'M', 'P', 'A', 'C', 'T', '3', 'D', '-', 'D', 'U', 'M', 'P', 0, 0, 0};
// header: magic(16) version(4) reserved(4) payload size(8) crc32(4) reserved(4) = 40 bytes
constexpr std::size_t kHeaderBytes = 40;

template <class T> struct is_std_array : std::false_type {};
template <class T, std::size_t N> struct is_std_array<std::array<T, N>> : std::true_type {};

class Writer {
 public:
  std::vector<char> buf;
  void raw(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    buf.insert(buf.end(), c, c + n);
  }
  template <class T> void operator()(const T& v) {
    if constexpr (std::is_arithmetic_v<T>) {
      raw(&v, sizeof v);
    } else if constexpr (is_std_array<T>::value) {
      for (const auto& e : v) (*this)(e);
    } else if constexpr (std::is_same_v<T, std::string>) {
      std::uint64_t n = v.size();
      raw(&n, sizeof n);
      raw(v.data(), v.size());
    } else {  // std::vector
      std::uint64_t n = v.size();
      raw(&n, sizeof n);
      for (const auto& e : v) (*this)(e);
    }
  }
};

class Reader {
 public:
  Reader(const std::vector<char>& b, std::size_t pos, const std::string& path) : b_(b), pos_(pos), path_(path) {}
  void raw(void* p, std::size_t n) {
    if (n > b_.size() - pos_) fail("data ends early");
    std::memcpy(p, b_.data() + pos_, n);
    pos_ += n;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("restart dump " + path_ + ": " + what + " at byte " + std::to_string(pos_));
  }
  template <class T> void operator()(T& v) {
    if constexpr (std::is_arithmetic_v<T>) {
      raw(&v, sizeof v);
    } else if constexpr (is_std_array<T>::value) {
      for (auto& e : v) (*this)(e);
    } else if constexpr (std::is_same_v<T, std::string>) {
      std::uint64_t n = 0;
      raw(&n, sizeof n);
      if (n > b_.size() - pos_) fail("string longer than the file");
      v.assign(b_.data() + pos_, n);
      pos_ += n;
    } else {  // std::vector: sizes come from the model, and must match
      std::uint64_t n = 0;
      raw(&n, sizeof n);
      if (n != v.size()) fail("array of " + std::to_string(n) + " entries where the model has " + std::to_string(v.size()) + " (a dump of another model?)");
      for (auto& e : v) (*this)(e);
    }
  }
  std::size_t pos() const { return pos_; }

 private:
  const std::vector<char>& b_;
  std::size_t pos_;
  std::string path_;
};

void write_header_fields(Writer& w, const DumpHeader& h) {
  w(h.deck_name);
  w(h.deck_text);
  w(h.plot_root);
  w(h.printed);
  w(h.dump_root);
  w(h.plot_word_size);
  w(h.member_size_factor);
  const OutputCursor& c = h.cursor;
  w(c.next_plot); w(c.next_history); w(c.plot_states); w(c.history_states); w(c.dumps_written);
  for (auto b : c.ascii_bytes) w(b);
  w(h.intfor_root); w(c.next_intfor); w(c.intfor_states);
  w(h.mesh_renumbered);
}

void read_header_fields(Reader& r, DumpHeader& h) {
  r(h.deck_name);
  r(h.deck_text);
  r(h.plot_root);
  r(h.printed);
  r(h.dump_root);
  r(h.plot_word_size);
  r(h.member_size_factor);
  OutputCursor& c = h.cursor;
  r(c.next_plot); r(c.next_history); r(c.plot_states); r(c.history_states); r(c.dumps_written);
  for (auto& b : c.ascii_bytes) r(b);
  r(h.intfor_root); r(c.next_intfor); r(c.intfor_states);
  r(h.mesh_renumbered);
}

std::vector<char> read_checked(const std::string& path, std::size_t& payload_start) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("restart dump " + path + ": cannot open: " + std::strerror(errno));
  std::vector<char> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (b.size() < kHeaderBytes) throw std::runtime_error("restart dump " + path + ": too short to be a dump (" + std::to_string(b.size()) + " bytes)");
  if (std::memcmp(b.data(), kMagic, sizeof kMagic) != 0) throw std::runtime_error("restart dump " + path + ": not an IMPACT-3D restart dump (bad magic)");
  std::uint32_t version = 0, crc = 0;
  std::uint64_t size = 0;
  std::memcpy(&version, b.data() + 16, 4);
  std::memcpy(&size, b.data() + 24, 8);
  std::memcpy(&crc, b.data() + 32, 4);
  if (version != kDumpVersion)
    throw std::runtime_error("restart dump " + path + ": format version " + std::to_string(version) + ", this impact3d reads version " + std::to_string(kDumpVersion));
  if (size != b.size() - kHeaderBytes)
    throw std::runtime_error("restart dump " + path + ": truncated or extended: header says " + std::to_string(size) + " payload bytes, file has " + std::to_string(b.size() - kHeaderBytes));
  if (crc32_of(b.data() + kHeaderBytes, std::size_t(size)) != crc) throw std::runtime_error("restart dump " + path + ": checksum mismatch: the dump is damaged");
  payload_start = kHeaderBytes;
  return b;
}

}  // namespace

void write_restart_dump(const std::string& path, const DumpHeader& h, State& s,
                        const SlidingInterfaces::RestartData& contact) {
  Writer w;
  write_header_fields(w, h);
  std::uint64_t nn = std::uint64_t(s.nn), ne = std::uint64_t(s.ne), nr = s.rigid.size();
  w(nn); w(ne); w(nr);
  s.visit_dynamic_fields(w);
  w(contact.forces);
  w(contact.admitted);
  w(contact.dtn);
  std::uint8_t has = contact.has ? 1 : 0;
  w(has);
  std::vector<char> out(kHeaderBytes, 0);
  std::memcpy(out.data(), kMagic, sizeof kMagic);
  std::uint32_t version = kDumpVersion;
  std::uint64_t size = w.buf.size();
  std::uint32_t crc = crc32_of(w.buf.data(), w.buf.size());
  std::memcpy(out.data() + 16, &version, 4);
  std::memcpy(out.data() + 24, &size, 8);
  std::memcpy(out.data() + 32, &crc, 4);
  out.insert(out.end(), w.buf.begin(), w.buf.end());
  const std::string tmp = path + ".tmp";
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("restart dump " + tmp + ": cannot open: " + std::strerror(errno));
  std::size_t done = 0;
  while (done < out.size()) {
    ssize_t n = ::write(fd, out.data() + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      int e = errno;
      ::close(fd);
      ::unlink(tmp.c_str());
      throw std::runtime_error("restart dump " + tmp + ": write failed: " + std::strerror(e));
    }
    done += std::size_t(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(tmp.c_str());
    throw std::runtime_error("restart dump " + tmp + ": fsync/close failed: " + std::strerror(errno));
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    ::unlink(tmp.c_str());
    throw std::runtime_error("restart dump " + path + ": rename failed: " + std::strerror(errno));
  }
}

DumpHeader read_restart_dump_header(const std::string& path) {
  std::size_t start = 0;
  std::vector<char> b = read_checked(path, start);
  Reader r(b, start, path);
  DumpHeader h;
  read_header_fields(r, h);
  return h;
}

void read_restart_dump_state(const std::string& path, State& s,
                             SlidingInterfaces::RestartData& contact) {
  std::size_t start = 0;
  std::vector<char> b = read_checked(path, start);
  Reader r(b, start, path);
  DumpHeader h;
  read_header_fields(r, h);
  std::uint64_t nn = 0, ne = 0, nr = 0;
  r(nn); r(ne); r(nr);
  if (nn != std::uint64_t(s.nn) || ne != std::uint64_t(s.ne) || nr != s.rigid.size())
    r.fail("model size differs from the deck (" + std::to_string(nn) + " nodes, " + std::to_string(ne) + " solids)");
  s.visit_dynamic_fields(r);
  s.elastic_dt_cycle = -1;  // the positions are the dump's: contact computes the elastic step itself
  // contact arrays: their sizes are whatever the dump says (empty without interfaces)
  for (auto* v : {&contact.forces, &contact.admitted}) {
    std::uint64_t n = 0;
    r.raw(&n, sizeof n);
    if (v == &contact.forces && n != 0 && n != 3 * std::uint64_t(s.nn)) r.fail("contact array of unexpected size");
    if (n > (b.size() - r.pos()) / sizeof(double)) r.fail("contact array longer than the dump");
    v->assign(std::size_t(n), 0.0);
    for (auto& e : *v) r(e);
  }
  r(contact.dtn);
  std::uint8_t has = 0;
  r(has);
  contact.has = has != 0;
  if (r.pos() != b.size()) r.fail("unexpected data after the state");
}

}  // namespace impact3d
