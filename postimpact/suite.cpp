#include "postimpact/suite.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "postimpact/command_file.h"
#include "postimpact/compare.h"
#include "postimpact/database.h"
#include "postimpact/elements.h"
#include "postimpact/history.h"
#include "postimpact/png_io.h"
#include "postimpact/quantities.h"
#include "postimpact/summary.h"

extern char** environ;

namespace postimpact {

namespace fs = std::filesystem;

bool SuiteDeck::plot_reference() const { return fs::exists(fs::path(ref_dir) / "d3plot"); }
bool SuiteDeck::summary_reference() const { return fs::exists(summary); }
std::string SuiteDeck::mode() const {
    return summary_check || (!plot_reference() && summary_reference()) ? "summary" : "plot";
}

std::vector<std::string> SuiteDeck::impact3d_args() const {
    std::vector<std::string> out{"i=" + deck, "o=d3hsp", "g=d3plot", "ncpu=1", "plotwords=8"};
    for (const auto& a : args) {
        const auto eq = a.find('=');
        bool replaced = false;
        if (eq != std::string::npos)
            for (auto& o : out)
                if (o.compare(0, eq + 1, a, 0, eq + 1) == 0) o = a, replaced = true;
        if (!replaced) out.push_back(a);
    }
    return out;
}

std::string xml_escape(const std::string& s) {
    std::string o;
    o.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': o += "&amp;"; break;
            case '<': o += "&lt;"; break;
            case '>': o += "&gt;"; break;
            case '"': o += "&quot;"; break;
            case '\'': o += "&#39;"; break;
            default:
                // XML 1.0 forbids most control characters: keep tab and newline only
                if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') o += '?';
                else o += c;
        }
    }
    return o;
}

namespace {

// options.txt / options/NAME.txt: "timeout SECONDS", "args WORD...", "reference plot|summary";
// '#' comments.  Later lines override earlier ones ("args" lines add up).
void read_deck_options(const fs::path& file, SuiteDeck& d) {
    std::ifstream f(file);
    if (!f) throw std::runtime_error(file.string() + ": cannot be read");
    int line_no = 0;
    for (std::string line; std::getline(f, line);) {
        ++line_no;
        const std::string where = file.string() + ":" + std::to_string(line_no) + ": ";
        std::vector<std::string> w;
        try {
            w = split_command(line);
        } catch (const std::exception& e) {
            throw std::runtime_error(where + e.what());
        }
        if (w.empty()) continue;
        if (w[0] == "timeout") {
            char* end = nullptr;
            const double t = w.size() == 2 ? std::strtod(w[1].c_str(), &end) : -1.0;
            if (w.size() != 2 || *end != '\0' || !(t >= 0) || !std::isfinite(t))
                throw std::runtime_error(where + "timeout: expected seconds >= 0 (0: none), as in 'timeout 600'");
            d.timeout = t;
        } else if (w[0] == "args") {
            for (std::size_t i = 1; i < w.size(); ++i) {
                if (w[i].rfind("i=", 0) == 0)
                    throw std::runtime_error(where + "args: the deck (i=) is the suite's; give the others");
                d.args.push_back(w[i]);
            }
        } else if (w[0] == "reference") {
            if (w.size() != 2 || (w[1] != "plot" && w[1] != "summary"))
                throw std::runtime_error(where + "reference: expected plot or summary");
            d.summary_check = w[1] == "summary";
        } else {
            throw std::runtime_error(where + "unknown option '" + w[0] + "' (timeout, args, reference)");
        }
    }
}

}  // namespace

std::vector<SuiteDeck> list_suite(const std::string& suite) {
    const fs::path root = fs::absolute(suite).lexically_normal();
    const fs::path decks = root / "decks";
    if (!fs::is_directory(decks)) throw std::runtime_error("suite " + suite + ": no folder " + decks.string());
    std::map<std::string, SuiteDeck> found;
    auto add = [&](const fs::path& p, bool summary_check) {
        const std::string name = p.stem().string();
        if (found.count(name))
            throw std::runtime_error("suite " + suite + ": two decks named " + name + " (" + found[name].deck + ", " +
                                     p.string() + ")");
        SuiteDeck d;
        d.name = name;
        d.deck = p.lexically_normal().string();
        d.ref_dir = (root / "reference" / name).string();
        d.summary = (root / "summaries" / (name + ".txt")).string();
        d.summary_check = summary_check;
        found[name] = d;
    };
    for (const auto& e : fs::directory_iterator(decks)) {
        if (!e.is_regular_file()) continue;
        const fs::path p = e.path();
        const std::string ext = p.extension().string();
        if (ext != ".dyn" && ext != ".k" && ext != ".key") continue;
        add(p, false);
    }
    // big decks kept by their summary, anywhere (paths from the suite folder)
    if (const fs::path list = root / "summary_decks.txt"; fs::exists(list)) {
        std::ifstream f(list);
        int line_no = 0;
        for (std::string line; std::getline(f, line);) {
            ++line_no;
            while (!line.empty() && (line.back() == ' ' || line.back() == '\t' || line.back() == '\r')) line.pop_back();
            const auto b = line.find_first_not_of(" \t");
            if (b == std::string::npos || line[b] == '#') continue;
            const fs::path p = fs::path(line.substr(b)).is_absolute() ? fs::path(line.substr(b)) : root / line.substr(b);
            if (!fs::is_regular_file(p))
                throw std::runtime_error(list.string() + ":" + std::to_string(line_no) + ": no deck " + p.lexically_normal().string());
            add(p, true);
        }
    }
    if (found.empty()) throw std::runtime_error("suite " + suite + ": no decks (*.dyn, *.k, *.key) in " + decks.string());
    const fs::path all = root / "options.txt";
    std::vector<SuiteDeck> out;
    for (auto& [k, d] : found) {
        if (fs::exists(all)) read_deck_options(all, d);
        if (const fs::path own = root / "options" / (d.name + ".txt"); fs::exists(own)) read_deck_options(own, d);
        out.push_back(std::move(d));
    }
    return out;
}

namespace {

double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string g6(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

// The solver: --impact3d, $IMPACT3D, impact3d beside this program or one folder up (the build
// tree: build/postimpact/postimpact, build/impact3d), impact3d on PATH.
std::string find_impact3d(const SuiteOptions& opt) {
    if (!opt.impact3d.empty()) return fs::absolute(opt.impact3d).string();
    if (const char* e = std::getenv("IMPACT3D"); e && *e) return fs::absolute(e).string();
    if (!opt.self.empty()) {
        const fs::path dir = fs::path(opt.self).parent_path();
        for (const fs::path& c : {dir / "impact3d", dir.parent_path() / "impact3d"})
            if (fs::is_regular_file(c) && access(c.c_str(), X_OK) == 0) return c.string();
    }
    if (const char* path = std::getenv("PATH")) {
        std::stringstream ss(path);
        for (std::string d; std::getline(ss, d, ':');) {
            const fs::path c = fs::path(d.empty() ? "." : d) / "impact3d";
            if (fs::is_regular_file(c) && access(c.c_str(), X_OK) == 0) return fs::absolute(c).string();
        }
    }
    throw std::runtime_error("cannot find impact3d (give --impact3d PATH or set IMPACT3D)");
}

// Starts argv in `cwd` with stdout and stderr to `log` and SOURCE_DATE_EPOCH=0; returns the pid.
pid_t spawn(const std::vector<std::string>& argv, const std::string& cwd, const std::string& log) {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&fa, cwd.c_str());
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind("SOURCE_DATE_EPOCH=", 0) != 0) env.emplace_back(*e);
    env.emplace_back("SOURCE_DATE_EPOCH=0");
    std::vector<char*> av, ev;
    for (const auto& a : argv) av.push_back(const_cast<char*>(a.c_str()));
    av.push_back(nullptr);
    for (const auto& e : env) ev.push_back(const_cast<char*>(e.c_str()));
    ev.push_back(nullptr);
    // the caller's process group: Ctrl-C on the terminal stops the jobs and their runs too
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, av[0], &fa, nullptr, av.data(), ev.data());
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(rc));
    return pid;
}

int exit_code(int st) {
    if (WIFEXITED(st)) return WEXITSTATUS(st);
    if (WIFSIGNALED(st)) return 128 + WTERMSIG(st);
    return 127;
}

int wait_exit(pid_t pid) {
    int st = 0;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) return 127;
    return exit_code(st);
}

// Waits for pid at most `timeout` seconds (0: no limit); past it, kills it (SIGKILL: impact3d is
// one process, its threads go with it) and sets timed_out.
int wait_exit(pid_t pid, double timeout, bool& timed_out) {
    timed_out = false;
    if (timeout <= 0) return wait_exit(pid);
    const double end = now_s() + timeout;
    for (;;) {
        int st = 0;
        const pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid) return exit_code(st);
        if (r < 0 && errno != EINTR) return 127;
        if (now_s() >= end) {
            timed_out = true;
            kill(pid, SIGKILL);
            return wait_exit(pid);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

std::string tail_lines(const std::string& path, int n) {
    std::ifstream f(path);
    std::vector<std::string> lines;
    for (std::string l; std::getline(f, l);) lines.push_back(l);
    std::string out;
    for (std::size_t k = lines.size() > static_cast<std::size_t>(n) ? lines.size() - n : 0; k < lines.size(); ++k)
        out += lines[k] + "\n";
    return out;
}

// The suite's tolerance file with the deck's own lines on top.
Tolerances deck_tolerances(const SuiteOptions& opt, const SuiteDeck& d) {
    Tolerances t;
    const fs::path base = fs::path(opt.suite) / "tolerances.txt";
    if (fs::exists(base)) t = Tolerances::read(base.string());
    const fs::path own = fs::path(opt.suite) / "tolerances" / (d.name + ".txt");
    if (fs::exists(own))
        for (const auto& [k, v] : Tolerances::read(own.string()).field) t.field[k] = v;
    return t;
}

// The fringe (and history variable) that shows a finding's field and component.
std::string quantity_for(const CompareFinding& f) {
    static const std::map<std::string, std::string> node_prefix = {{"coords", "d"}, {"vel", "v"}, {"acc", "a"}};
    if (auto it = node_prefix.find(f.field); it != node_prefix.end() && f.what == "node" && f.comp.size() == 1)
        return it->second + f.comp;
    if (f.field == "temp" && f.what == "node") return "temp";
    if (f.field == "stress" && !f.comp.empty() && f.what != "material") return f.comp;
    if (f.field == "eps" && f.what != "material") return "eps";
    return "";
}

struct Picture {
    std::string file, caption;
};

// Reference and new pictures at one state with one fringe range, and time-history overlays.
// The mark command's kind for a finding's location ("" when it has none: a global or material value).
std::string mark_kind(const CompareFinding& f) {
    if (f.id <= 0) return "";
    if (f.what == "node") return "node";
    if (f.what == "elem" || f.what == "solid") return "solid";
    if (f.what == "thick shell") return "tshell";
    if (f.what == "shell" || f.what == "beam") return f.what;
    return "";
}

// The reference and new pictures mark the worst location (the node or element of the largest
// difference outside tolerance): kv gets "marked" (what, which quantity) and "mark_FILE" (the
// pixel where each picture has it).
std::vector<Picture> make_pictures(const std::string& ref, const std::string& run, const fs::path& dir,
                                   const CompareFinding* worst, std::map<std::string, std::string>& kv,
                                   std::ostream& log) {
    std::vector<Picture> pics;
    Database A(ref), B(run);
    std::string key = worst ? quantity_for(*worst) : "";
    if (key.empty()) key = "eps";
    Quantity q;
    find_quantity(key, q);
    const int ns = std::min(A.num_states(), B.num_states());
    if (ns == 0) return pics;
    const int state = worst && worst->state >= 1 && worst->state <= ns ? worst->state - 1 : ns - 1;
    // one range for both pictures: every value of the quantity in the two states
    double lo = INFINITY, hi = -INFINITY;
    for (Database* db : {&A, &B}) {
        const auto& s = db->state(state);
        const std::vector<double> v = q.where == Quantity::Where::Node ? node_values(q, db->geometry(), s)
                                                                        : element_values(q, db->geometry(), db->layout(), s);
        for (double x : v)
            if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    }
    if (!(lo <= hi)) lo = 0, hi = 1;
    if (hi - lo <= 1e-300 + 1e-12 * std::max(std::fabs(lo), std::fabs(hi))) {
        const double w = std::max(std::fabs(lo) * 1e-6, 1e-30);
        lo -= w, hi += w;
    }
    char range_lo[40], range_hi[40];
    std::snprintf(range_lo, sizeof range_lo, "%.17g", lo);
    std::snprintf(range_hi, sizeof range_hi, "%.17g", hi);
    std::ostringstream quiet;
    Session s(quiet);
    s.execute({"outdir", dir.string()});
    s.execute({"size", "640", "480"});
    s.execute({"plotsize", "800", "500"});
    s.execute({"fringe", key});
    s.execute({"range", range_lo, range_hi});
    const std::string st = std::to_string(state + 1);
    const std::string kind = worst ? mark_kind(*worst) : "";
    std::string marked;
    if (!kind.empty()) {
        marked = (worst->what == "elem" ? std::string("elem") : worst->what) + " " + std::to_string(worst->id);
        const std::string label = marked + (worst->comp.empty() ? " " + worst->field : " " + worst->comp);
        s.execute({"mark", kind, std::to_string(worst->id), label});
        kv["marked"] = label + " (" + worst->field + " at state " + std::to_string(worst->state) + ": the largest difference outside tolerance)";
    }
    auto picture = [&](const std::string& db, const std::string& title, const std::string& file) {
        s.execute({"open", db});
        s.execute({"title", title});
        s.execute({"picture", file, st});
        if (!kind.empty() && !s.mark_spots().empty())
            kv["mark_" + file] = g6(s.mark_spots().front().x) + " " + g6(s.mark_spots().front().y);
    };
    picture(ref, "Reference", "ref.png");
    picture(run, "New run", "new.png");
    const std::string what = q.label + ", state " + st + " (t " + g6(B.time(state)) + ")" +
                             (marked.empty() ? "" : ", " + marked + " ringed");
    pics.push_back({"ref.png", "Reference: " + what});
    pics.push_back({"new.png", "New run: " + what});

    // overlays: the energies, and the quantity at the worst node / element
    const Font font("");
    Units units;
    auto overlay = [&](const std::vector<std::string>& words, const std::string& file, const std::string& title) {
        HistoryData h;
        for (int k = 0; k < 2; ++k) {
            Database& db = k == 0 ? A : B;
            const HistoryData one = extract_history(db, parse_history(words, db));
            for (std::size_t i = 0; i < one.series.size(); ++i) {
                Series se = one.series[i];
                se.name = (k == 0 ? "reference: " : "new: ") + se.name;
                h.series.push_back(std::move(se));
                h.dims.push_back(one.dims[i]);
            }
            if (k == 1) h.time = one.time;
        }
        write_png((dir / file).string(), plot_history(h, title, units, 800, 500, font));
        pics.push_back({file, title});
        // the difference new - reference of each curve, state by state (same times), on its own
        // scale: where and when the run leaves its reference
        const std::size_t n = h.series.size() / 2;
        HistoryData d;
        for (std::size_t i = 0; i < n; ++i) {
            const Series& a = h.series[i];
            const Series& b = h.series[n + i];
            Series se;
            se.name = "new - reference: " + a.name.substr(std::strlen("reference: "));
            for (std::size_t k = 0; k < std::min(a.y.size(), b.y.size()); ++k) {
                se.x.push_back(b.x[k]);
                se.y.push_back(b.y[k] - a.y[k]);
            }
            d.series.push_back(std::move(se));
            d.dims.push_back(h.dims[i]);
        }
        d.time = h.time;
        const std::string dfile = file.substr(0, file.size() - 4) + "_diff.png";
        const std::string dtitle = "Difference " + title.substr(0, title.find(':')) + ": new run - reference";
        write_png((dir / dfile).string(), plot_history(d, dtitle, units, 800, 500, font));
        pics.push_back({dfile, dtitle});
    };
    overlay({"global", "ke", "ie", "te"}, "energies.png", "Energies: reference and new run");
    if (worst && !worst->what.empty() && worst->what != "model" && worst->id > 0) {
        const std::string hk = worst->what == "material" ? (worst->comp == "internal" ? "ie" : worst->comp == "kinetic" ? "ke" : worst->comp == "hourglass" ? "hg" : "")
                                                         : quantity_for(*worst);
        std::string group = worst->what == "elem" ? "element" : worst->what;
        if (worst->what == "wall") group = "wall";
        const std::string var = worst->what == "wall" ? "fn" : worst->what == "interface" ? (worst->comp.size() == 1 ? "f" + worst->comp : "fm") : hk;
        if (!var.empty()) {
            try {
                overlay({group, std::to_string(worst->id), var}, "worst.png",
                        group + " " + std::to_string(worst->id) + " " + var + ": reference and new run");
            } catch (const std::exception& e) {
                log << "  (no history of " << group << " " << worst->id << " " << var << ": " << e.what() << ")\n";
            }
        }
    }
    return pics;
}

void write_result(const fs::path& dir, const std::map<std::string, std::string>& kv,
                  const std::vector<std::string>& findings, const std::vector<Picture>& pics) {
    const fs::path tmp = dir / "result.txt.tmp";
    {
        std::ofstream f(tmp);
        for (const auto& [k, v] : kv) f << k << " " << one_line(v) << "\n";
        for (const auto& x : findings) f << "finding " << one_line(x) << "\n";
        for (const auto& p : pics) f << "picture " << p.file << " " << one_line(p.caption) << "\n";
        if (!f) throw std::runtime_error("cannot write " + tmp.string());
    }
    fs::rename(tmp, dir / "result.txt");
}

std::string finding_text(const CompareFinding& f) {
    std::string s = f.field + " at state " + std::to_string(f.state) + " (t " + g6(f.time) + ")";
    if (!f.what.empty()) s += " " + f.what + (f.id > 0 ? " " + std::to_string(f.id) : std::string());
    if (!f.comp.empty()) s += " " + f.comp;
    s += ": reference " + g6(f.a) + ", new " + g6(f.b) + ", |a-b| " + g6(f.absd) + ", rel " + g6(f.reld) + ", " +
         (std::isinf(f.ratio) ? std::string("nothing allowed") : g6(f.ratio) + " x the allowed");
    return s;
}

struct DeckResult {
    std::string name, status = "missing", mode, message, deck, marked;
    double run_s = 0, compare_s = 0;
    std::vector<std::string> findings;
    std::vector<Picture> pictures;
};

DeckResult read_result(const fs::path& dir, const std::string& name) {
    DeckResult r;
    r.name = name;
    std::ifstream f(dir / "result.txt");
    if (!f) {
        r.message = "no result (" + (dir / "result.txt").string() + "): the deck's job did not run or did not finish";
        return r;
    }
    for (std::string line; std::getline(f, line);) {
        const auto sp = line.find(' ');
        const std::string k = line.substr(0, sp), v = sp == std::string::npos ? "" : line.substr(sp + 1);
        if (k == "status") r.status = v;
        else if (k == "mode") r.mode = v;
        else if (k == "message") r.message = v;
        else if (k == "deck") r.deck = v;
        else if (k == "marked") r.marked = v;
        else if (k == "run_seconds") r.run_s = std::atof(v.c_str());
        else if (k == "compare_seconds") r.compare_s = std::atof(v.c_str());
        else if (k == "finding") r.findings.push_back(v);
        else if (k == "picture") {
            const auto s2 = v.find(' ');
            r.pictures.push_back({v.substr(0, s2), s2 == std::string::npos ? "" : v.substr(s2 + 1)});
        }
    }
    return r;
}

std::vector<SuiteDeck> selected(const SuiteOptions& opt) {
    std::vector<SuiteDeck> all = list_suite(opt.suite);
    if (opt.decks.empty()) return all;
    std::vector<SuiteDeck> out;
    for (const auto& n : opt.decks) {
        auto it = std::find_if(all.begin(), all.end(), [&](const SuiteDeck& d) { return d.name == n; });
        if (it == all.end()) throw std::runtime_error("suite " + opt.suite + ": no deck named " + n);
        out.push_back(*it);
    }
    return out;
}

std::string read_file(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

// How a deck's job ended: pass, fail, error or update, and the one-line message.
struct Outcome {
    std::string status, message;
};

// One deck's job: its folders and what its result.txt records.
struct DeckJob {
    const SuiteDeck& d;
    std::string mode;
    fs::path dir, run;
    std::map<std::string, std::string> kv;
    std::vector<std::string> findings;
    std::vector<Picture> pics;

    std::string new_db() const { return (run / "d3plot").string(); }
};

// The deck's folder emptied of an earlier job's results, and the deck's own record.
DeckJob start_deck_job(const SuiteOptions& opt, const SuiteDeck& d) {
    DeckJob job{d, d.mode(), fs::absolute(opt.outdir) / d.name, {}, {}, {}, {}};
    job.run = job.dir / "run";
    fs::create_directories(job.dir);
    for (const char* old : {"result.txt", "compare.txt", "ref.png", "new.png", "energies.png", "worst.png",
                            "energies_diff.png", "worst_diff.png"})
        fs::remove(job.dir / old);
    fs::remove_all(job.run);
    fs::create_directories(job.run);
    job.kv = {{"name", d.name}, {"deck", d.deck}, {"mode", job.mode}};
    if (d.timeout > 0) job.kv["timeout"] = g6(d.timeout);
    if (!d.args.empty()) {
        std::string a;
        for (const auto& w : d.args) a += (a.empty() ? "" : " ") + w;
        job.kv["args"] = a;
    }
    return job;
}

// Writes result.txt, logs the verdict (and the findings of a failure); the job's exit code.
int finish_deck_job(DeckJob& job, const Outcome& o, std::ostream& log) {
    job.kv["status"] = o.status;
    job.kv["message"] = o.message;
    write_result(job.dir, job.kv, job.findings, job.pics);
    const std::string& s = o.status;
    log << job.d.name << ": " << (s == "pass" ? "PASS" : s == "fail" ? "FAIL" : s == "update" ? "UPDATED" : "ERROR")
        << (o.message.empty() ? "" : " (" + o.message + ")") << "\n";
    if (s == "fail" || s == "error")
        for (const auto& f : job.findings) log << "  " << f << "\n";
    return s == "pass" || s == "update" ? 0 : s == "fail" ? 1 : 2;
}

// An error when a comparing job has no reference to compare with.
std::optional<Outcome> missing_reference(const SuiteOptions& opt, const SuiteDeck& d, const std::string& mode) {
    if (opt.update) return std::nullopt;
    if (mode == "summary" && !d.summary_reference())
        return Outcome{"error", "no reference: no " + d.summary + " (postimpact suite SUITE --update stores one)"};
    if (!d.plot_reference() && !d.summary_reference())
        return Outcome{"error", "no reference: neither " + d.ref_dir + "/d3plot nor " + d.summary +
                                    " (postimpact suite SUITE --update stores one)"};
    return std::nullopt;
}

// Runs impact3d on the deck in the job's run folder; an outcome when the run did not end normally.
std::optional<Outcome> run_deck_impact3d(const SuiteOptions& opt, DeckJob& job) {
    const double t0 = now_s();
    int rc = 0;
    bool timed_out = false;
    const std::string run_log = (job.dir / "run.log").string();
    try {
        std::vector<std::string> argv = job.d.impact3d_args();
        argv.insert(argv.begin(), find_impact3d(opt));
        rc = wait_exit(spawn(argv, job.run.string(), run_log), job.d.timeout, timed_out);
    } catch (const std::exception& e) {
        return Outcome{"error", e.what()};
    }
    job.kv["run_seconds"] = g6(now_s() - t0);
    job.kv["run_exit"] = std::to_string(rc);
    if (timed_out) {
        const std::string why = "timeout after " + g6(job.d.timeout) + " s";
        job.findings.push_back(why + ": impact3d was killed; the end of run.log: " + tail_lines(run_log, 3));
        return Outcome{"fail", why + " (impact3d killed)"};
    }
    if (rc != 0) {
        job.findings.push_back("impact3d exited with " + std::to_string(rc) + "; the end of run.log: " + tail_lines(run_log, 3));
        return Outcome{"error", "impact3d exited with " + std::to_string(rc) + " (run.log)"};
    }
    return std::nullopt;
}

// --update: the run's d3plot family (plot mode) or its summary becomes the reference.
Outcome store_deck_reference(const DeckJob& job) {
    const SuiteDeck& d = job.d;
    if (job.mode == "plot") {
        fs::create_directories(d.ref_dir);
        for (const auto& e : fs::directory_iterator(d.ref_dir))
            if (e.path().filename().string().rfind("d3plot", 0) == 0) fs::remove(e.path());
        for (const auto& e : fs::directory_iterator(job.run))
            if (e.path().filename().string().rfind("d3plot", 0) == 0) fs::copy_file(e.path(), fs::path(d.ref_dir) / e.path().filename());
        return {"update", "stored " + d.ref_dir + "/d3plot*"};
    }
    try {
        const Summary sm = summarize(job.new_db(), (job.run / "d3hsp").string());
        fs::create_directories(fs::path(d.summary).parent_path());
        std::ofstream f(d.summary);
        write_summary(sm, f);
        f.close();
        if (!f) throw std::runtime_error("cannot write " + d.summary);
    } catch (const std::exception& e) {
        return {"error", e.what()};
    }
    return {"update", "stored " + d.summary};
}

const char* compare_status(int crc) { return crc == 0 ? "pass" : crc == 1 ? "fail" : "error"; }

// The one-line message of a plot comparison: the worst value and the counts outside tolerance.
std::string plot_compare_message(const CompareResult& res, int crc) {
    if (crc == 2) return "not comparable: " + res.problem;
    if (crc != 1) return "";
    std::string message, counts;
    for (const auto& r : res.fields)
        if (r.outside > 0) counts += (counts.empty() ? "" : ", ") + std::to_string(r.outside) + " " + r.field;
    if (!res.worst.empty()) message = "worst: " + finding_text(res.worst.front()) + "; values outside tolerance: " + counts;
    if (res.states_a != res.states_b)
        message += std::string(message.empty() ? "" : "; ") + "the reference has " + std::to_string(res.states_a) +
                   " states, the run " + std::to_string(res.states_b);
    return message;
}

// Compares the run's d3plot family with the reference's (compare.txt), then makes the pictures.
Outcome compare_deck_plot(const SuiteOptions& opt, const Tolerances& tol, DeckJob& job, std::ostream& log) {
    const double t1 = now_s();
    const std::string ref = (fs::path(job.d.ref_dir) / "d3plot").string();
    CompareResult res;
    int crc = 0;
    {
        std::ofstream cmp(job.dir / "compare.txt");
        try {
            CompareOptions co;
            co.tol = tol;
            co.report = 10;
            crc = compare_databases(ref, job.new_db(), co, cmp, &res);
        } catch (const std::exception& e) {
            cmp << e.what() << "\n";
            return {"error", std::string("cannot compare: ") + e.what()};
        }
    }
    job.kv["compare_seconds"] = g6(now_s() - t1);
    for (const auto& f : res.worst) job.findings.push_back(finding_text(f));
    const std::string message = plot_compare_message(res, crc);
    if (opt.pictures && crc != 2) {
        try {
            job.pics = make_pictures(ref, job.new_db(), job.dir, res.worst.empty() ? nullptr : &res.worst.front(), job.kv, log);
        } catch (const std::exception& e) {
            log << job.d.name << ": no pictures: " << e.what() << "\n";
        }
    }
    return {compare_status(crc), message};
}

// Compares the run's summary (summary.txt) with the stored one (compare.txt); each line outside is a finding.
Outcome compare_deck_summary(const Tolerances& tol, DeckJob& job) {
    const double t1 = now_s();
    int crc = 0;
    {
        std::ofstream cmp(job.dir / "compare.txt");
        try {
            const Summary s = summarize(job.new_db(), (job.run / "d3hsp").string());
            std::ofstream sf(job.dir / "summary.txt");
            write_summary(s, sf);
            std::ostringstream text;
            crc = compare_summaries(read_summary(job.d.summary), s, tol, text, job.d.summary, (job.dir / "summary.txt").string());
            cmp << text.str();
            std::istringstream lines(text.str());
            for (std::string l; std::getline(lines, l);)
                if (l.find("OUTSIDE") != std::string::npos || l.find("MISSING") != std::string::npos ||
                    l.find("DIFFERENT (not") != std::string::npos) {
                    while (l.find("  ") != std::string::npos) l.replace(l.find("  "), 2, " ");
                    job.findings.push_back("summary " + l);
                }
        } catch (const std::exception& e) {
            cmp << e.what() << "\n";
            return {"error", std::string("cannot compare: ") + e.what()};
        }
    }
    job.kv["compare_seconds"] = g6(now_s() - t1);
    const std::string message = crc == 0 ? "" : job.findings.empty() ? "summaries differ" : job.findings.front();
    return {compare_status(crc), message};
}

}  // namespace

int run_suite_deck(const SuiteOptions& opt, const SuiteDeck& d, std::ostream& log) {
    DeckJob job = start_deck_job(opt, d);
    if (auto o = missing_reference(opt, d, job.mode)) return finish_deck_job(job, *o, log);
    Tolerances tol;
    try {
        if (!opt.update) tol = deck_tolerances(opt, d);
    } catch (const std::exception& e) {
        return finish_deck_job(job, {"error", e.what()}, log);
    }
    if (auto o = run_deck_impact3d(opt, job)) return finish_deck_job(job, *o, log);
    if (opt.update) return finish_deck_job(job, store_deck_reference(job), log);
    const Outcome o = job.mode == "plot" ? compare_deck_plot(opt, tol, job, log) : compare_deck_summary(tol, job);
    return finish_deck_job(job, o, log);
}

int run_suite(const SuiteOptions& opt, std::ostream& log) {
    const std::vector<SuiteDeck> decks = selected(opt);
    if (opt.self.empty()) throw std::runtime_error("run_suite: the program's own path is unknown");
    int jobs = opt.jobs > 0 ? opt.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const std::string impact3d = find_impact3d(opt);
    const fs::path out = fs::absolute(opt.outdir);
    fs::create_directories(out);
    log << "suite " << opt.suite << ": " << decks.size() << " deck(s), " << jobs << " at a time, impact3d "
        << impact3d << ", results in " << out.string() << "\n";
    std::map<pid_t, std::string> running;
    std::size_t next = 0;
    int failed_jobs = 0;
    auto reap = [&]() {
        int st = 0;
        const pid_t pid = waitpid(-1, &st, 0);
        if (pid < 0) return;
        const auto it = running.find(pid);
        if (it == running.end()) return;
        const std::string name = it->second;
        running.erase(it);
        if (exit_code(st) != 0) ++failed_jobs;
        // the job's verdict line (findings follow it)
        std::ifstream jl(out / name / "job.log");
        std::string verdict;
        for (std::string l; std::getline(jl, l);)
            for (const char* v : {": PASS", ": FAIL", ": UPDATED", ": ERROR"})
                if (l.rfind(name + v, 0) == 0) verdict = l;
        log << (verdict.empty() ? name + ": (no verdict in job.log, exit " + std::to_string(exit_code(st)) + ")" : verdict)
            << "\n" << std::flush;
    };
    while (next < decks.size() || !running.empty()) {
        if (next < decks.size() && static_cast<int>(running.size()) < jobs) {
            const SuiteDeck& d = decks[next++];
            fs::create_directories(out / d.name);
            std::vector<std::string> argv{opt.self, "suite", fs::absolute(opt.suite).string(), "-o", out.string(),
                                          "--job", d.name, "--impact3d", impact3d};
            if (!opt.pictures) argv.push_back("--no-pictures");
            if (opt.update) argv.push_back("--update");
            running[spawn(argv, "", (out / d.name / "job.log").string())] = d.name;
        } else {
            reap();
        }
    }
    if (opt.update) return failed_jobs == 0 ? 0 : 1;  // a deck whose run failed stores nothing
    return gather_suite(opt, log);
}

int gather_suite(const SuiteOptions& opt, std::ostream& log) {
    const std::vector<SuiteDeck> decks = selected(opt);
    const fs::path out = fs::absolute(opt.outdir);
    fs::create_directories(out);
    std::vector<DeckResult> rs;
    int failures = 0, errors = 0;
    double total = 0;
    for (const auto& d : decks) {
        rs.push_back(read_result(out / d.name, d.name));
        const auto& r = rs.back();
        if (r.status == "fail") ++failures;
        else if (r.status != "pass") ++errors;
        total += r.run_s + r.compare_s;
    }
    const std::string suite_name = fs::absolute(opt.suite).lexically_normal().filename().string().empty()
                                       ? fs::absolute(opt.suite).lexically_normal().parent_path().filename().string()
                                       : fs::absolute(opt.suite).lexically_normal().filename().string();
    // JUnit XML (the form Jenkins, GitLab and GitHub read): one testsuite, one testcase a deck
    {
        std::ofstream x(out / "junit.xml");
        x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          << "<testsuites name=\"" << xml_escape(suite_name) << "\" tests=\"" << rs.size() << "\" failures=\""
          << failures << "\" errors=\"" << errors << "\" time=\"" << g6(total) << "\">\n"
          << "  <testsuite name=\"" << xml_escape(suite_name) << "\" tests=\"" << rs.size() << "\" failures=\""
          << failures << "\" errors=\"" << errors << "\" skipped=\"0\" time=\"" << g6(total) << "\">\n";
        for (const auto& r : rs) {
            x << "    <testcase classname=\"postimpact.suite." << xml_escape(suite_name) << "\" name=\""
              << xml_escape(r.name) << "\" time=\"" << g6(r.run_s + r.compare_s) << "\">\n";
            if (r.status != "pass") {
                const bool fail = r.status == "fail";
                std::string body;
                for (const auto& f : r.findings) body += f + "\n";
                const std::string cmp = read_file(out / r.name / "compare.txt");
                if (!cmp.empty()) body += "\n" + cmp;
                x << "      <" << (fail ? "failure" : "error") << " type=\""
                  << (fail ? (r.message.rfind("timeout after ", 0) == 0 ? "timeout" : "outside tolerance")
                           : r.status == "missing" ? "no result" : "error")
                  << "\" message=\""
                  << xml_escape(r.message) << "\">" << xml_escape(body) << "</" << (fail ? "failure" : "error") << ">\n";
            }
            x << "    </testcase>\n";
        }
        x << "  </testsuite>\n</testsuites>\n";
        if (!x) throw std::runtime_error("cannot write " + (out / "junit.xml").string());
    }
    // the HTML page: a table of every deck, then each deck's pictures side by side
    {
        std::ofstream h(out / "report.html");
        h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Suite "
          << xml_escape(suite_name) << "</title>\n<style>\n"
             "body{font-family:DejaVu Sans,Arial,sans-serif;margin:1.5em;color:#222}\n"
             "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 8px;text-align:left;vertical-align:top}\n"
             ".pass{background:#d9f2d9}.fail{background:#f8d0d0}.error,.missing{background:#f8e0b0}\n"
             "section{margin-top:1.5em;border-top:2px solid #888}section.fail,section.error,section.missing{border-top:4px solid #c00}\n"
             ".pics{display:flex;flex-wrap:wrap;gap:10px}figure{margin:0}figcaption{font-size:90%}\n"
             "img{max-width:640px;border:1px solid #ccc}pre{font-size:85%;background:#f4f4f4;padding:6px;overflow:auto}\n"
             "li.diff{color:#a00}.mark{color:#909}\n</style>\n</head>\n<body>\n";
        h << "<h1>Suite " << xml_escape(suite_name) << ": " << (rs.size() - failures - errors) << " passed, "
          << failures << " failed, " << errors << " error(s)</h1>\n";
        h << "<p>" << xml_escape(fs::absolute(opt.suite).lexically_normal().string()) << " &mdash; " << rs.size()
          << " deck(s); machine-readable: <a href=\"junit.xml\">junit.xml</a></p>\n";
        h << "<table>\n<tr><th>deck</th><th>result</th><th>run (s)</th><th>compare (s)</th><th>what differs</th></tr>\n";
        for (const auto& r : rs)
            h << "<tr class=\"" << xml_escape(r.status) << "\"><td><a href=\"#" << xml_escape(r.name) << "\">"
              << xml_escape(r.name) << "</a></td><td>" << xml_escape(r.status) << "</td><td>" << g6(r.run_s)
              << "</td><td>" << g6(r.compare_s) << "</td><td>" << xml_escape(r.message) << "</td></tr>\n";
        h << "</table>\n";
        for (const auto& r : rs) {
            h << "<section class=\"" << xml_escape(r.status) << "\" id=\"" << xml_escape(r.name) << "\">\n<h2>"
              << xml_escape(r.name) << ": " << xml_escape(r.status) << "</h2>\n";
            if (!r.deck.empty()) h << "<p>deck " << xml_escape(r.deck) << " (" << xml_escape(r.mode) << " reference)</p>\n";
            if (!r.message.empty()) h << "<p><b>" << xml_escape(r.message) << "</b></p>\n";
            if (!r.findings.empty()) {
                h << "<ul>\n";
                for (const auto& f : r.findings) h << "<li class=\"diff\">" << xml_escape(f) << "</li>\n";
                h << "</ul>\n";
            }
            if (!r.marked.empty())
                h << "<p class=\"mark\">Marked on the pictures (magenta ring): " << xml_escape(r.marked) << "</p>\n";
            if (!r.pictures.empty()) {
                h << "<div class=\"pics\">\n";
                for (const auto& p : r.pictures)
                    h << "<figure><img src=\"" << xml_escape(r.name + "/" + p.file) << "\" alt=\"" << xml_escape(p.caption)
                      << "\"><figcaption>" << xml_escape(p.caption) << "</figcaption></figure>\n";
                h << "</div>\n";
            }
            h << "<p><a href=\"" << xml_escape(r.name) << "/compare.txt\">compare.txt</a> &middot; <a href=\""
              << xml_escape(r.name) << "/run.log\">run.log</a></p>\n</section>\n";
        }
        h << "</body>\n</html>\n";
        if (!h) throw std::runtime_error("cannot write " + (out / "report.html").string());
    }
    log << "suite " << suite_name << ": " << (rs.size() - failures - errors) << " passed, " << failures << " failed, "
        << errors << " error(s) of " << rs.size() << "\n";
    for (const auto& r : rs)
        if (r.status != "pass") log << "  " << r.name << ": " << r.status << (r.message.empty() ? "" : ": " + r.message) << "\n";
    log << "wrote " << (out / "junit.xml").string() << "\nwrote " << (out / "report.html").string() << "\n";
    return failures + errors == 0 ? 0 : 1;
}

}  // namespace postimpact
