#pragma once
// Shared by the session's source files (not installed): the menus' alternatives, the slider
// ranges and small element helpers.

#include "phigs/store/Element.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace acsynt::session_detail {

using namespace phigs;

inline const char* const title = "ACSYNT B-SPLINE MODULE V1.2.2";
inline const std::vector<std::string> mainItems{"FILE",   "VIEW", "CURVE_MAP", "SURF_REDN",
                                                "MODELS", "UNDO", "REDO",      "EXIT"};
inline const std::vector<std::string> fileItems{"RETURN",   "READ_MODEL", "READ_CURVE_FILE", "SAVE_MODEL",
                                                "ARCHIVE",  "RETRIEVE",   "EXPORT",          "IMPORT",
                                                "HARDCOPY", "EXIT"};
inline const std::vector<std::string> viewItems{"RETURN",   "ONE_VIEW",         "FOUR_VIEWS",
                                                "SHADE",    "WIREFRAME",        "HULL_ON",
                                                "HULL_OFF", "CENTRE_ON_MARKER", "RESET_VIEW"};
inline const std::vector<std::string> curveItems{"RETURN",     "LOAD_CURVE",   "DEFINE_POINT",
                                                 "FLIP_CURVE", "ROTATE_CURVE", "MAP_PREVIEW",
                                                 "MAP_CURVE",  "DISPLAY_ALL"};
inline const std::vector<std::string> confirmItems{"ACCEPT", "REJECT"};
inline const std::vector<std::string> reductionItems{"RETURN",       "REDUCE_U", "REDUCE_W", "REDUCE_U&W",
                                                     "BY_TOLERANCE", "BY_COUNT", "ERROR_MAP"};
inline const std::vector<std::string> modelItems{"RETURN", "NEXT_MODEL", "PREVIOUS_MODEL",
                                                 "LIST",   "NAME_MODEL", "DELETE_MODEL"};
inline const std::vector<std::string> padItems{"NORTH_WEST", "NORTH", "NORTH_EAST", "WEST", "CENTRE", "EAST",
                                               "SOUTH_WEST", "SOUTH", "SOUTH_EAST", "DONE"};
inline const char* const sliderNames[] = {"U", "W", "ROTATE", "ZOOM"};
inline const double sliderLow[] = {0, 0, -180, 0.25};
inline const double sliderHigh[] = {1, 1, 180, 8};

/// How a menu alternative is shown: underscores as blanks (SURF_REDN keeps its name).
inline std::string shown(const std::string& item) {
    if (item == "SURF_REDN") return item;
    std::string s = item;
    std::replace(s.begin(), s.end(), '_', ' ');
    return s;
}

inline std::string number(double v, int digits = 6) {
    std::ostringstream out;
    out.precision(digits);
    out << v;
    return out.str();
}

inline Element colourAttr(ElementType type, const glm::dvec3& rgb) {
    return ColourAttribute{type, Colour::fromRgb(rgb)};
}

inline Element textAt(const glm::dvec3& at, const std::string& s) {
    return TextElement{at, {1, 0, 0}, {0, 1, 0}, s, false};
}

}  // namespace acsynt::session_detail
