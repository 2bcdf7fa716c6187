#include "postimpact/command_file.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "postimpact/history.h"
#include "postimpact/png_io.h"

namespace postimpact {

namespace {

bool to_int(const std::string& s, int& v) {
    if (s.empty()) return false;
    std::size_t pos = 0;
    try { v = std::stoi(s, &pos); } catch (...) { return false; }
    return pos == s.size();
}

bool to_double(const std::string& s, double& v) {
    if (s.empty()) return false;
    std::size_t pos = 0;
    try { v = std::stod(s, &pos); } catch (...) { return false; }
    return pos == s.size() && std::isfinite(v);
}

bool on_off(const std::string& s, bool& v) {
    if (s == "on" || s == "yes" || s == "true" || s == "1") { v = true; return true; }
    if (s == "off" || s == "no" || s == "false" || s == "0") { v = false; return true; }
    return false;
}

std::string with_ext(const std::string& path, const std::string& ext) {
    std::filesystem::path p(path);
    if (p.extension().empty()) p += ext;
    return p.string();
}

}  // namespace

std::vector<std::string> split_command(const std::string& line) {
    std::vector<std::string> w;
    std::string cur;
    bool in_quotes = false, have = false;
    for (char c : line) {
        if (in_quotes) {
            if (c == '"') in_quotes = false;
            else cur += c;
            continue;
        }
        if (c == '#') break;
        if (c == '"') { in_quotes = true; have = true; continue; }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            if (have) { w.push_back(cur); cur.clear(); have = false; }
            continue;
        }
        cur += c;
        have = true;
    }
    if (in_quotes) throw CommandError("unterminated quoted string");
    if (have) w.push_back(cur);
    return w;
}

Session::Session(std::ostream& log) : log_(log) {}
Session::~Session() = default;

Database& Session::db(const std::string& cmd) {
    if (!db_) throw CommandError(cmd + ": no database open (open PATH, or give it on the command line)");
    return *db_;
}

Renderer& Session::renderer() {
    if (!renderer_) renderer_ = std::make_unique<Renderer>();
    return *renderer_;
}

const Font& Session::font() {
    if (!font_) font_ = std::make_unique<Font>(font_path_);
    return *font_;
}

std::string Session::out_path(const std::string& name) const {
    std::filesystem::path p(name);
    if (!p.is_absolute() && !outdir_.empty()) p = std::filesystem::path(outdir_) / p;
    if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());  // frames anim/f_
    return p.string();
}

namespace {
double wall_now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double cpu_now() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }
}  // namespace

void Session::wrote(const std::string& path) {
    written_.push_back(path);
    ++actions_;
    log_ << "wrote " << path;
    if (timing_) {
        char b[96];
        std::snprintf(b, sizeof b, "  (%.3f s wall, %.3f s cpu)", wall_now() - t0_wall_, cpu_now() - t0_cpu_);
        log_ << b;
    }
    log_ << "\n";
    t0_wall_ = wall_now();
    t0_cpu_ = cpu_now();
}

int Session::parse_state(const std::string& s, const std::string& cmd) {
    Database& d = db(cmd);
    const int n = d.num_states();
    if (n == 0) throw CommandError(cmd + ": the database has no states");
    if (s == "first") return 0;
    if (s == "last") return n - 1;
    if (s == "middle") return (n - 1) / 2;
    int k = 0;
    if (to_int(s, k)) {
        if (k < 0) k = n + 1 + k;  // -1 = last
        if (k < 1 || k > n)
            throw CommandError(cmd + ": state " + s + " out of range (1.." + std::to_string(n) + ")");
        return k - 1;
    }
    const auto eq = s.find('=');
    double t = 0;
    if (eq != std::string::npos && (s.substr(0, eq) == "t" || s.substr(0, eq) == "time") && to_double(s.substr(eq + 1), t)) {
        int best = 0;
        for (int i = 1; i < n; ++i)
            if (std::fabs(d.time(i) - t) < std::fabs(d.time(best) - t)) best = i;
        return best;
    }
    throw CommandError(cmd + ": expected a state (number, first, middle, last, t=TIME), found '" + s + "'");
}

std::vector<int> Session::parse_states(const std::vector<std::string>& w, std::size_t from, const std::string& cmd) {
    Database& d = db(cmd);
    const int n = d.num_states();
    if (n == 0) throw CommandError(cmd + ": the database has no states");
    std::vector<int> out;
    if (from >= w.size()) {  // default: five states from first to last
        const int k = std::min(n, 5);
        for (int i = 0; i < k; ++i) out.push_back(k == 1 ? n - 1 : static_cast<int>(std::lround(static_cast<double>(i) * (n - 1) / (k - 1))));
        return out;
    }
    if (w[from] == "all") {
        for (int i = 0; i < n; ++i) out.push_back(i);
        return out;
    }
    if (w[from] == "every" || w[from] == "count") {
        int k = 0;
        if (from + 1 >= w.size() || !to_int(w[from + 1], k) || k < 1)
            throw CommandError(cmd + ": " + w[from] + " needs a positive number");
        if (w[from] == "every") {
            for (int i = 0; i < n; i += k) out.push_back(i);
            if (out.back() != n - 1) out.push_back(n - 1);
        } else {
            k = std::min(k, n);
            for (int i = 0; i < k; ++i) out.push_back(k == 1 ? n - 1 : static_cast<int>(std::lround(static_cast<double>(i) * (n - 1) / (k - 1))));
        }
        return out;
    }
    for (std::size_t i = from; i < w.size(); ++i) {
        // "a:b" ranges (1-based, inclusive)
        const auto colon = w[i].find(':');
        if (colon != std::string::npos) {
            const int a = parse_state(w[i].substr(0, colon), cmd), b = parse_state(w[i].substr(colon + 1), cmd);
            for (int k = a; k <= b; ++k) out.push_back(k);
            continue;
        }
        out.push_back(parse_state(w[i], cmd));
    }
    if (out.empty()) throw CommandError(cmd + ": no states selected (a range A:B needs A <= B)");
    return out;
}

void Session::execute_line(const std::string& line, const std::string& where) {
    std::vector<std::string> w;
    try {
        w = split_command(line);
    } catch (const CommandError& e) {
        throw CommandError(where.empty() ? e.what() : where + ": " + e.what());
    }
    if (!w.empty()) execute(w, where);
}

namespace {

// Throws the command's usage when it has fewer than lo or more than hi arguments.
void need_args(const std::vector<std::string>& w, std::size_t lo, std::size_t hi, const char* usage) {
    const std::size_t na = w.size() - 1;
    if (na < lo || na > hi) throw CommandError(w[0] + ": usage: " + usage);
}

// The words after the first `from` joined by single spaces.
std::string join_from(const std::vector<std::string>& w, std::size_t from) {
    std::string t;
    for (std::size_t i = from; i < w.size(); ++i) t += (i > from ? " " : "") + w[i];
    return t;
}

}  // namespace

// The command table: each command word and the member that carries it out.
const std::vector<Session::CommandEntry>& Session::commands() {
    static const std::vector<CommandEntry> table = {
        {"open", &Session::cmd_open},         {"database", &Session::cmd_open},
        {"outdir", &Session::cmd_outdir},     {"size", &Session::cmd_size},
        {"plotsize", &Session::cmd_size},     {"view", &Session::cmd_view},
        {"up", &Session::cmd_up},             {"mirror", &Session::cmd_mirror},
        {"fringe", &Session::cmd_fringe},     {"range", &Session::cmd_range},
        {"bands", &Session::cmd_bands},       {"supersample", &Session::cmd_supersample},
        {"timing", &Session::cmd_timing},     {"average", &Session::cmd_switch},
        {"edges", &Session::cmd_switch},      {"legend", &Session::cmd_switch},
        {"triad", &Session::cmd_switch},      {"units", &Session::cmd_units},
        {"scale", &Session::cmd_scale},       {"font", &Session::cmd_font},
        {"title", &Session::cmd_title},       {"mark", &Session::cmd_mark},
        {"state", &Session::cmd_state},       {"picture", &Session::cmd_picture},
        {"sequence", &Session::cmd_sequence}, {"frames", &Session::cmd_frames},
        {"history", &Session::cmd_history},   {"echo", &Session::cmd_echo},
        {"default", &Session::cmd_default},
    };
    return table;
}

void Session::execute(const std::vector<std::string>& w, const std::string& where) {
    const std::string& c = w.at(0);
    t0_wall_ = wall_now();
    t0_cpu_ = cpu_now();
    try {
        const auto& table = commands();
        const auto it = std::find_if(table.begin(), table.end(), [&](const CommandEntry& e) { return c == e.name; });
        if (it == table.end()) throw CommandError("unknown command '" + c + "'");
        (this->*(it->run))(w);
    } catch (const CommandError& e) {
        throw CommandError(where.empty() ? e.what() : where + ": " + e.what());
    } catch (const std::exception& e) {
        throw CommandError((where.empty() ? "" : where + ": ") + c + ": " + e.what());
    }
}

void Session::cmd_open(const Words& w) {
    need_args(w, 1, 1, "open PATH");
    db_ = std::make_unique<Database>(w[1]);
    state_ = -1;
    log_ << "opened " << w[1] << ": " << db_->geometry().num_nodes() << " nodes, "
         << db_->geometry().num_hexes() << " solids, ";
    const auto& g = db_->geometry();
    if (g.num_tshells()) log_ << g.num_tshells() << " thick shells, ";
    if (g.num_beams()) log_ << g.num_beams() << " beams, ";
    if (g.num_shells()) log_ << g.num_shells() << " shells, ";
    log_ << db_->num_states() << " states\n";
}

void Session::cmd_outdir(const Words& w) {
    need_args(w, 1, 1, "outdir DIR");
    outdir_ = w[1];
    std::filesystem::create_directories(outdir_);
}

void Session::cmd_size(const Words& w) {
    need_args(w, 1, 2, "size W H (or WxH)");
    int W = 0, H = 0;
    bool ok = false;
    if (w.size() == 3) ok = to_int(w[1], W) && to_int(w[2], H);
    else if (auto x = w[1].find('x'); x != std::string::npos) ok = to_int(w[1].substr(0, x), W) && to_int(w[1].substr(x + 1), H);
    if (!ok || W < 64 || H < 64 || W > 8192 || H > 8192) throw CommandError(w[0] + ": expected a width and a height in 64..8192");
    if (w[0] == "size") { ps_.width = W; ps_.height = H; }
    else { plot_w_ = W; plot_h_ = H; }
}

void Session::cmd_view(const Words& w) {
    need_args(w, 1, 2, "view NAME | view AZIMUTH ELEVATION");
    if (w.size() == 2) {
        if (!named_view(w[1], ps_.view))
            throw CommandError("view: unknown view '" + w[1] + "' (iso front back left right top bottom +x -x +y -y +z -z, or AZ EL)");
        return;
    }
    double az = 0, el = 0;
    if (!to_double(w[1], az) || !to_double(w[2], el) || el < -90 || el > 90)
        throw CommandError("view: expected azimuth and elevation in degrees (elevation -90..90)");
    ps_.view.azimuth = az;
    ps_.view.elevation = el;
}

void Session::cmd_up(const Words& w) {
    need_args(w, 1, 1, "up x|y|z");
    if (w[1] == "x") ps_.view.up = 0;
    else if (w[1] == "y") ps_.view.up = 1;
    else if (w[1] == "z") ps_.view.up = 2;
    else throw CommandError("up: expected x, y or z");
}

void Session::cmd_mirror(const Words& w) {
    need_args(w, 1, 1, "mirror none|x|y|z|xy|xz|yz|xyz");
    try { ps_.mirror = parse_mirror(w[1]); } catch (const std::invalid_argument& e) { throw CommandError(e.what()); }
}

void Session::cmd_fringe(const Words& w) {
    need_args(w, 1, 1, "fringe QUANTITY|none|material");
    Quantity q;
    if (w[1] != "none" && w[1] != "material" && !find_quantity(w[1], q))
        throw CommandError("fringe: unknown quantity '" + w[1] + "' (none material " + quantity_keys() + ")");
    // the normalized key, with its "@surface" / "@ipK" suffix
    const auto at = w[1].find('@');
    ps_.fringe = (w[1] == "none" || w[1] == "material") ? w[1]
                                                         : q.key + (at != std::string::npos ? w[1].substr(at) : std::string());
}

void Session::cmd_range(const Words& w) {
    need_args(w, 1, 2, "range auto | range MIN MAX");
    if (w.size() == 2 && w[1] == "auto") {
        ps_.range_auto = true;
        return;
    }
    double lo = 0, hi = 0;
    if (w.size() != 3 || !to_double(w[1], lo) || !to_double(w[2], hi) || !(hi > lo))
        throw CommandError("range: expected auto or MIN MAX with MIN < MAX");
    ps_.range_auto = false;
    ps_.range_lo = lo;
    ps_.range_hi = hi;
}

void Session::cmd_bands(const Words& w) {
    need_args(w, 1, 1, "bands N");
    int n = 0;
    if (!to_int(w[1], n) || n < 2 || n > 64) throw CommandError("bands: expected 2..64");
    ps_.bands = n;
}

void Session::cmd_supersample(const Words& w) {
    need_args(w, 1, 1, "supersample N");
    int n = 0;
    if (!to_int(w[1], n) || n < 1 || n > 4) throw CommandError("supersample: expected 1..4");
    ps_.supersample = n;
}

void Session::cmd_timing(const Words& w) {
    need_args(w, 1, 1, "timing on|off");
    if (!on_off(w[1], timing_)) throw CommandError("timing: expected on or off");
}

void Session::cmd_switch(const Words& w) {
    need_args(w, 1, 1, "on|off");
    const std::string& c = w[0];
    bool v = false;
    if (!on_off(w[1], v)) throw CommandError(c + ": expected on or off");
    (c == "average" ? ps_.average : c == "edges" ? ps_.edges : c == "legend" ? ps_.legend : ps_.triad) = v;
}

void Session::cmd_units(const Words& w) {
    need_args(w, 1, 1, "units si|none");
    if (w[1] == "si" || w[1] == "SI") ps_.units.si = true;
    else if (w[1] == "none") ps_.units.si = false;
    else throw CommandError("units: expected si or none");
}

void Session::cmd_scale(const Words& w) {
    need_args(w, 1, 1, "scale FACTOR");
    double f = 0;
    if (!to_double(w[1], f)) throw CommandError("scale: expected a number");
    ps_.deform_scale = f;
}

void Session::cmd_font(const Words& w) {
    need_args(w, 1, 1, "font PATH");
    font_path_ = w[1];
    font_ = std::make_unique<Font>(font_path_);
}

void Session::cmd_title(const Words& w) {
    if (w.size() == 1) throw CommandError("title: usage: title TEXT | title auto");
    if (w.size() == 2 && w[1] == "auto") ps_.title.clear();
    else ps_.title = join_from(w, 1);
}

void Session::cmd_mark(const Words& w) {
    if (w.size() == 2 && w[1] == "off") {
        ps_.marks.clear();
        return;
    }
    if (w.size() < 3) throw CommandError("mark: usage: mark node|elem|solid|tshell|beam|shell ID [LABEL] | mark off");
    static const char* const kinds[] = {"node", "elem", "element", "solid", "tshell", "beam", "shell"};
    if (std::find(std::begin(kinds), std::end(kinds), w[1]) == std::end(kinds))
        throw CommandError("mark: unknown kind '" + w[1] + "' (node elem solid tshell beam shell)");
    PictureMark m;
    m.what = w[1] == "element" ? "elem" : w[1];
    if (!to_int(w[2], m.id) || m.id <= 0) throw CommandError("mark: expected a positive user id, not '" + w[2] + "'");
    m.label = join_from(w, 3);
    ps_.marks.push_back(m);
}

void Session::cmd_state(const Words& w) {
    need_args(w, 1, 1, "state N|first|middle|last|t=TIME");
    state_ = parse_state(w[1], w[0]);
}

void Session::cmd_picture(const Words& w) {
    need_args(w, 1, 2, "picture FILE [STATE]");
    Database& d = db(w[0]);
    const int si = w.size() == 3 ? parse_state(w[2], w[0]) : (state_ >= 0 ? state_ : d.num_states() - 1);
    if (d.num_states() == 0) throw CommandError("picture: the database has no states");
    if (dry_run_) { d.state(si); return; }
    const std::string path = out_path(with_ext(w[1], ".png"));
    write_png(path, make_picture(d, {si}, ps_, renderer(), font(), {}, &mark_spots_));
    wrote(path);
}

void Session::cmd_sequence(const Words& w) {
    if (w.size() < 2) throw CommandError("sequence: usage: sequence FILE [STATES...|all|every K|count N]");
    Database& d = db(w[0]);
    const std::vector<int> st = parse_states(w, 2, w[0]);
    if (st.size() > 16) throw CommandError("sequence: at most 16 states side by side (frames makes an animation)");
    if (dry_run_) { for (int si : st) d.state(si); return; }
    const std::string path = out_path(with_ext(w[1], ".png"));
    write_png(path, make_picture(d, st, ps_, renderer(), font()));
    wrote(path);
}

void Session::cmd_frames(const Words& w) {
    if (w.size() < 2) throw CommandError("frames: usage: frames PREFIX [STATES...|all|every K|count N]");
    Database& d = db(w[0]);
    const std::vector<int> st = w.size() == 2 ? parse_states({"frames", "x", "all"}, 2, w[0]) : parse_states(w, 2, w[0]);
    if (dry_run_) { for (int si : st) d.state(si); return; }
    int k = 0;
    for (int si : st) {
        char num[16];
        std::snprintf(num, sizeof num, "%04d", ++k);
        const std::string path = out_path(w[1] + num + ".png");
        write_png(path, make_picture(d, {si}, ps_, renderer(), font(), st));
        wrote(path);
    }
}

void Session::cmd_history(const Words& w) {
    if (w.size() < 3) throw CommandError("history: usage: history FILE energy | global VARS | material ID VARS | node ID VARS | element ID VARS ...");
    Database& d = db(w[0]);
    std::vector<HistoryCurve> curves;
    try {
        curves = parse_history(std::vector<std::string>(w.begin() + 2, w.end()), d);
    } catch (const std::invalid_argument& e) {
        throw CommandError(e.what());
    }
    const HistoryData h = extract_history(d, curves);
    if (dry_run_) return;
    const std::string png = out_path(with_ext(w[1], ".png"));
    std::filesystem::path csv(png);
    csv.replace_extension(".csv");
    std::string title = ps_.title.empty() ? d.geometry().title : ps_.title;
    while (!title.empty() && title.back() == ' ') title.pop_back();
    write_png(png, plot_history(h, title, ps_.units, plot_w_, plot_h_, font()));
    wrote(png);
    write_csv(csv.string(), h, ps_.units);
    written_.push_back(csv.string());
    log_ << "wrote " << csv.string() << "\n";
}

void Session::cmd_echo(const Words& w) {
    log_ << join_from(w, 1) << "\n";
}

void Session::cmd_default(const Words& w) {
    need_args(w, 0, 0, "default");
    default_set();
}

void Session::run_text(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    std::string line;
    int ln = 0;
    while (std::getline(in, line)) {
        ++ln;
        execute_line(line, name + ":" + std::to_string(ln));
    }
}

void Session::run_file(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw CommandError("cannot read command file " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    run_text(ss.str(), path);
}

void Session::default_set() {
    Database& d = db("default");
    const std::string saved_fringe = ps_.fringe;
    ps_.fringe = "eps";
    if (d.num_states() > 0) {
        execute({"picture", "eps_first", "first"}, "default");
        execute({"picture", "eps_middle", "middle"}, "default");
        execute({"picture", "eps_last", "last"}, "default");
        execute({"sequence", "eps_sequence"}, "default");
        execute({"history", "energies", "energy"}, "default");
        // contact forces: every rigid wall's normal force and every interface's resultant
        const auto& g = d.geometry();
        if (g.num_rigid_walls + g.num_interfaces > 0) {
            std::vector<std::string> h = {"history", "forces"};
            for (int w = 1; w <= g.num_rigid_walls; ++w) h.insert(h.end(), {"wall", std::to_string(w), "fn"});
            for (int i = 1; i <= g.num_interfaces; ++i) h.insert(h.end(), {"interface", std::to_string(i), "fm"});
            execute(h, "default");
        }
    }
    ps_.fringe = saved_fringe;
}

}  // namespace postimpact
