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

// A node or element marked on a picture: a magenta ring (with four ticks) around its projected
// position (an element's centroid in the state drawn) and a label beside it, drawn over the mesh
// (a hidden element shows through).  The suite report marks the worst difference this way.
struct PictureMark {
    std::string what = "elem";  // node, elem (any family), solid, tshell, beam, shell
    int id = 0;                 // user id
    std::string label;          // empty: "WHAT ID"
};
// Where a mark was drawn: pixel centre coordinates from the picture's top-left corner, one per
// mark and panel (panel-major).
struct MarkSpot {
    double x = 0, y = 0;
    int panel = 0;
};
inline constexpr Rgb kMarkColor{255, 0, 255};

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
    std::vector<PictureMark> marks;
};

// states: 0-based indices shown (one: a single picture; several: side by side).  fit_states:
// the states used for the window and the automatic fringe range (frames of an animation pass
// all of them so that every frame has the same view and legend); empty: `states`.  spots: where
// the marks were drawn.  Throws std::invalid_argument for a mark on an unknown node or element.
Image make_picture(Database& db, const std::vector<int>& states, const PictureSettings& ps,
                   Renderer& renderer, const Font& font, const std::vector<int>& fit_states = {},
                   std::vector<MarkSpot>* spots = nullptr);

}  // namespace postimpact
