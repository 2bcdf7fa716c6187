// Keyword decks: the control and database cards (*CONTROL_..., *DATABASE_..., and the keywords
// read and ignored), read by their tables (keyword_cards.cpp) and built into model.control.

#include "impact3d/input/keyword_families.h"

#include <algorithm>
#include <cmath>

namespace impact3d::kw {

namespace {

void read_termination(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordControls& c) {
  c.have_termination = true;
  if (b.data.empty()) {
    ctx.missing_card(b, "card 1 (ENDTIM)");
    return;
  }
  KeywordValues v = ctx.values(b, 0, s.card(""));
  c.end_time = v["ENDTIM"];
  if (v.passed("ENDCYC")) c.end_cycle = int(v.integer("ENDCYC"));
  c.dtmin = v["DTMIN"];
  c.endmas = v["ENDMAS"];
  if (c.endmas >= 1e8) c.endmas = 0;  // LS-DYNA's default 1e8: no limit
}

void read_timestep(KeywordValues& v, KeywordControls& c) {
  c.dtinit = v["DTINIT"];
  c.tssfac = v["TSSFAC"];
  c.dt2ms = v["DT2MS"];
  c.erode = v.integer("ERODE") == 1;
  c.ms1st = v.integer("MS1ST") == 1;
}

// The time-history and output intervals of the ASCII databases.
void read_ascii_database(const std::string& n, double dt, KeywordControls& c) {
  if (n == "DATABASE_NODOUT") c.nodout_dt = dt;
  if (n == "DATABASE_ELOUT") c.elout_dt = dt;
  if (n == "DATABASE_GLSTAT") c.glstat_dt = dt;
  if (n == "DATABASE_NCFORC") c.ncforc_dt = dt;
  if (n == "DATABASE_SPCFORC") c.spcforc = dt > 0 ? 1 : 0;
}

// The cards of one keyword of the family (b.data is not empty).
void read_cards(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordControls& c) {
  const std::string& n = b.name;
  KeywordValues v = ctx.values(b, 0, s.cards.front());
  if (n == "CONTROL_TIMESTEP") {
    read_timestep(v, c);
  } else if (n == "CONTROL_CONTACT") {
    c.slsfac = v["SLSFAC"];
    c.shlthk = int(v.integer("SHLTHK"));
    c.penopt = int(v.integer("PENOPT"));
  } else if (n == "CONTROL_OUTPUT") {
    c.ikedit = int(v.integer("IKEDIT"));
  } else if (n == "CONTROL_HOURGLASS") {
    c.ihq = int(v.integer("IHQ"));
    c.qh = v["QH"];
  } else if (n == "CONTROL_BULK_VISCOSITY") {
    c.q1 = v["Q1"];
    c.q2 = v["Q2"];
    c.btype = 1;
  } else if (n == "CONTROL_SHELL") {
    if (b.data.size() > 1) c.rotascl = ctx.values(b, 1, s.card("card 2"))["ROTASCL"];
  } else if (n == "DATABASE_BINARY_D3PLOT") {
    c.d3plot_dt = v["DT"];
  } else if (n == "DATABASE_BINARY_D3THDT") {
    // the binary time-history database's interval: IMPACT-3D has one time-history interval
    // (d3thdt and the ASCII tables), and this DT takes precedence over the ASCII ones
    c.d3thdt_dt = v["DT"];
  } else if (n == "DATABASE_BINARY_INTFOR") {
    c.intfor_dt = v["DT"];
  } else if (n == "DATABASE_BINARY_D3DUMP" || n == "DATABASE_BINARY_RUNRSF") {
    if (v.passed("CYCL")) (n == "DATABASE_BINARY_D3DUMP" ? c.d3dump : c.runrsf) = int(std::lround(v["CYCL"]));
  } else {
    read_ascii_database(n, v["DT"], c);
  }
}

// *DATABASE_HISTORY_NODE / _SOLID / _SHELL / _BEAM: ids 8 a card; _NODE_SET / _SOLID_SET: set
// ids 8 a card; _ID: one id and a heading a card.
void read_history(const Block& b, KeywordContext& ctx, const KeywordSpec& s, KeywordControls& c) {
  RHistory h;
  h.solid = b.name.rfind("DATABASE_HISTORY_SOLID", 0) == 0;
  h.shell = b.name.rfind("DATABASE_HISTORY_SHELL", 0) == 0;
  h.beam = b.name.rfind("DATABASE_HISTORY_BEAM", 0) == 0;
  h.sets = b.name.size() > 4 && b.name.compare(b.name.size() - 4, 4, "_SET") == 0;
  const KeywordCardLayout& layout = s.card("");
  const std::size_t n = layout.fixed ? 1 : layout.fields.size();  // _ID: the id, not the heading
  for (std::size_t k = 0; k < b.data.size(); ++k) {
    if (is_blank(b.data[k].line->text)) continue;
    KeywordValues v = ctx.fields(b, k, layout);
    for (std::size_t f = 0; f < n; ++f) {
      const long long id = v.integer_at(f);
      if (id != 0) {
        h.ids.push_back(int(id));
        h.refs.push_back(v.card().ref(layout.fields[f].index));
      }
    }
  }
  c.histories.push_back(std::move(h));
}

// *COMMENT is ignored (as by LS-DYNA), except the IMPACT-3D lines the converter writes there
// for fields LS-DYNA has no keyword for (any other: error 1312).
void read_comment(const Block& b, KeywordContext& ctx, KeywordControls& c) {
  for (const KLine& l : b.data) {
    const std::string t = upper(rtrim(l.line->text));
    if (t.rfind("IMPACT-3D ", 0) != 0) continue;
    std::vector<std::string> tok;
    for (std::size_t p = 0; p < t.size();) {
      const std::size_t s = t.find_first_not_of(' ', p);
      if (s == std::string::npos) break;
      const std::size_t e = t.find(' ', s);
      tok.push_back(t.substr(s, e == std::string::npos ? std::string::npos : e - s));
      p = e == std::string::npos ? t.size() : e;
    }
    long long v = 0;
    const bool num = parse_fortran_int(tok.back(), v) == FieldStatus::ok;
    if (num && tok.size() == 3 && tok[1] == "INTERFACE_SEGMENTS") {
      c.interface_segments = int(v);
    } else if (num && tok.size() == 3 && tok[1] == "VISCOSITY_FLAG") {
      c.viscosity_flag = int(v);
    } else if (num && tok.size() == 3 && tok[1] == "REACTION_PRINT_FLAG") {
      c.reaction_flag = int(v);
    } else if (num && tok.size() == 4 && tok[1] == "INITIALLY_ELASTIC" && tok[2] == "PART") {
      c.initially_elastic.insert(int(v));
    } else {
      Location loc;
      loc.file = l.file->name();
      loc.line = l.line->number;
      loc.card = "*COMMENT";
      ctx.diag.add(1312, loc, "unknown IMPACT-3D line: " + rtrim(l.line->text));
    }
  }
}

}  // namespace

bool read_control_database(const Block& b, KeywordContext& ctx, KeywordControls& c) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || (s->family != KeywordFamily::control_database && s->family != KeywordFamily::ignored)) return false;
  if (s->once) ctx.once(b);
  if (b.name.rfind("DATABASE_HISTORY_", 0) == 0) {
    read_history(b, ctx, *s, c);
    return true;
  }
  if (b.name == "TITLE") {
    if (!b.data.empty()) {
      const std::string_view t = b.data[0].line->text;
      c.title = rtrim(t.substr(0, std::min<std::size_t>(80, t.size())));
    }
    return true;
  }
  if (b.name == "COMMENT") {
    read_comment(b, ctx, c);
    return true;
  }
  if (b.name == "DATABASE_BINARY_INTFOR") {
    // the interface-force database (written with s=, default intfor beside g=)
    c.intfor_given = true;
    c.intfor_dt = 0;
  }
  if (b.name == "CONTROL_TERMINATION") {
    read_termination(b, ctx, *s, c);
  } else if (s->family == KeywordFamily::ignored) {
    // the cards' checks only: *CONTROL_SOLUTION SOLN 1 (thermal only) and 2 (coupled) change
    // the analysis: refused, not ignored
    if (!s->cards.empty() && !b.data.empty()) ctx.values(b, 0, s->cards.front());
    Location loc;
    loc.file = b.kw.file->name();
    loc.line = b.kw.line->number;
    loc.card = b.keyword;
    ctx.diag.add(2008, loc, s->note);
  } else if (!b.data.empty()) {
    read_cards(b, ctx, *s, c);
  }
  return true;
}

void build_controls(const KeywordControls& c, const std::string& main_deck, Model& m, Diagnostics& diag) {
  if (c.title) m.title = *c.title;
  ControlData& k = m.control;
  if (c.interface_segments) k.interface_segments_out = *c.interface_segments;
  if (c.viscosity_flag) k.viscosity_flag = *c.viscosity_flag;
  k.nmmat = int(m.materials.size());
  k.numnp = m.num_nodes();
  k.numelh = m.num_hexes();
  if (!c.have_termination) {
    Location loc;
    loc.file = main_deck;
    diag.add(1311, loc, "*CONTROL_TERMINATION (ENDTIM) is required");
  }
  k.end_time = c.end_time;
  k.end_cycle = c.end_cycle;
  k.min_step_factor = c.dtmin;
  k.initial_dt = c.dtinit;
  k.tssf = c.tssfac;
  k.mass_scaling_dt = c.dt2ms;
  k.mass_scaling_first_only = c.ms1st;
  k.end_mass_percent = c.endmas;
  k.erode_small_steps = c.erode;
  k.penalty_scale = c.slsfac;
  k.report_interval = c.ikedit;
  k.plot_interval = c.d3plot_dt > 0 ? c.d3plot_dt : c.end_time / 20;
  const double th = c.d3thdt_dt > 0 ? c.d3thdt_dt : c.nodout_dt > 0 ? c.nodout_dt : c.elout_dt > 0 ? c.elout_dt : c.glstat_dt > 0 ? c.glstat_dt : 0;
  k.th_interval = th > 0 ? th : c.end_time / 1000;
  k.interface_out_interval = c.ncforc_dt;
  k.reaction_print_flag = c.reaction_flag >= 0 ? c.reaction_flag : c.spcforc;
  k.restart_dump_cycles = c.d3dump;
  k.running_restart_cycles = c.runrsf;
  if (c.intfor_given) k.intfor_interval = c.intfor_dt;
}

}  // namespace impact3d::kw
