#pragma once
// The printed output file (o=, default d3hsp): an echo of what the input phase understood, in
// words and units, then the run log.

#include <ostream>
#include <string>

#include "common/messages.h"
#include "impact3d/model/model.h"

namespace impact3d {

// Summary of the model as understood: controls, materials with derived constants, counts,
// walls, interfaces, initial velocities, time histories.
void write_model_summary(std::ostream& os, const Model& m);

// Short counts summary (the lines --check prints on stdout).
void write_counts(std::ostream& os, const Model& m);

void write_diagnostics(std::ostream& os, const Diagnostics& diag);

}  // namespace impact3d
