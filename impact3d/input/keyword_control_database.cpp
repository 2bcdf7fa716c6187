// Keyword decks: the control and database cards (*CONTROL_..., *DATABASE_..., and the keywords
// read and ignored), read by their tables (keyword_cards.cpp) and built into model.control.

#include "impact3d/input/keyword_families.h"

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

}  // namespace

bool read_control_database(const Block& b, KeywordContext& ctx, KeywordControls& c) {
  const KeywordSpec* s = find_keyword_spec(b.name);
  if (!s || (s->family != KeywordFamily::control_database && s->family != KeywordFamily::ignored)) return false;
  if (s->once) ctx.once(b);
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

void build_controls(const KeywordControls& c, const std::string& main_deck, int reaction_flag, Model& m,
                    Diagnostics& diag) {
  ControlData& k = m.control;
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
  k.reaction_print_flag = reaction_flag >= 0 ? reaction_flag : c.spcforc;
  k.restart_dump_cycles = c.d3dump;
  k.running_restart_cycles = c.runrsf;
  if (c.intfor_given) k.intfor_interval = c.intfor_dt;
}

}  // namespace impact3d::kw
