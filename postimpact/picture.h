// Pictures of the deformed mesh: one state, or several states side by side (a sequence), with
// title, quantity, time, colour legend and axis triad.
#pragma once

#include <string>
#include <vector>

#include "postimpact/camera.h"
#include "postimpact/database.h"
#include "postimpact/image.h"
#include "postimpact/mesh_surface.h"
#include "postimpact/quantities.h"
#include "postimpact/render_osmesa.h"
#include "postimpact/text_freetype.h"

namespace postimpact {

struct PictureSettings {
    int width = 1600, height = 1200;
    View view;
    Mirror mirror;
    std::string fringe = "eps";   // a quantity key, "none" or "material"
    bool range_auto = true;
    double range_lo = 0, range_hi = 1;
    int bands = 10;
    bool average = true;          // element quantities averaged to the nodes (smooth)
    bool edges = true;
    bool legend = true;
    bool triad = true;
    std::string title;            // empty: the database title
    Units units;
    int supersample = 2;
    double deform_scale = 1.0;    // displacement magnification (1 = true shape)
};

// states: 0-based indices shown (one: a single picture; several: side by side).  fit_states:
// the states used for the window and the automatic fringe range (frames of an animation pass
// all of them so that every frame has the same view and legend); empty: `states`.
Image make_picture(Database& db, const std::vector<int>& states, const PictureSettings& ps,
                   Renderer& renderer, const Font& font, const std::vector<int>& fit_states = {});

}  // namespace postimpact
