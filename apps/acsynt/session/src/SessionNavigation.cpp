// Navigation of the views (mouse drags, wheel, keys in a window; the `view` directive), the
// help overlay, and the key shortcuts for UNDO and REDO.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "acsynt/ModelFile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

namespace {

double wrapDegrees(double a) {
    a = std::fmod(a + 180.0, 360.0);
    return (a < 0 ? a + 360.0 : a) - 180.0;
}

}  // namespace

void Session::rotateView(double azimuth, double elevation) {
    core_.azimuth = wrapDegrees(core_.azimuth + azimuth);
    core_.elevation = std::clamp(core_.elevation + elevation, -89.0, 89.0);
    navigated();
}

void Session::zoomView(double factor) {
    if (!(factor > 0) || !std::isfinite(factor)) return;
    core_.zoom = std::clamp(core_.zoom * factor, sliderLow[3], sliderHigh[3]);
    navigated();
}

void Session::panView(glm::dvec2 pixels) {
    // The model follows the pointer in the 3D view's plane: one pixel is the view's world
    // window over its pixel height.
    const auto [lo, hi] = modelBounds();
    const double radius = std::max(glm::length(hi - lo) / 2, 1e-6);
    const PixelBox b = layout_.viewBox(core_.fourViews ? 4 : 1, core_.fourViews);
    const double aspect = (b.x1 - b.x0) / std::max(b.y1 - b.y0, 1.0);
    const double half = obliqueHalfSize(radius) / core_.zoom;
    const double perPixel = 2 * (aspect >= 1 ? half : half / aspect) / std::max(b.y1 - b.y0, 1.0);
    const glm::dvec3 n = obliqueDirection();
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), n));
    const glm::dvec3 up = glm::cross(n, right);
    // Within the places a view line may name (setView), so the recording replays.
    core_.viewCentre = glm::clamp(
        core_.viewCentre.value_or((lo + hi) / 2.0) - pixels.x * perPixel * right + pixels.y * perPixel * up,
        glm::dvec3(-acsynt::kModelMaxLength), glm::dvec3(acsynt::kModelMaxLength));
    navigated();
}

glm::dvec3 Session::obliqueDirection() const {
    const double az = glm::radians(core_.azimuth), el = glm::radians(core_.elevation);
    return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

std::pair<glm::dvec3, glm::dvec3> Session::modelBounds() const {
    glm::dvec3 lo(-1), hi(1);
    if (!core_.models.empty()) {
        lo = glm::dvec3(1e300);
        hi = glm::dvec3(-1e300);
        for (const Component& c : core_.models.current().components)
            for (const glm::dvec3& p : c.surface.points) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    }
    return {lo, hi};
}

void Session::navigated() {
    updateViews();
    drawScreen();  // the ROTATE and ZOOM sliders follow
    // One `view` line per run of navigation: the recording replays where it ended.
    char line[200];
    const glm::dvec3 c = core_.viewCentre.value_or(glm::dvec3(0));
    if (core_.viewCentre)
        std::snprintf(line, sizeof line, "view %.17g %.17g %.17g %.17g %.17g %.17g", core_.azimuth,
                      core_.elevation, core_.zoom, c.x, c.y, c.z);
    else
        std::snprintf(line, sizeof line, "view %.17g %.17g %.17g", core_.azimuth, core_.elevation,
                      core_.zoom);
    const std::size_t at = core_.input->history().size();
    if (!extraLines_.empty() && extraLines_.back().first == at &&
        extraLines_.back().second.rfind("view ", 0) == 0)
        extraLines_.back().second = line;
    else
        extraLines_.emplace_back(at, line);
}

void Session::setView(const std::vector<std::string>& a) {
    std::vector<double> v;
    for (const auto& word : a)
        if (const auto x = parseNumber(word)) v.push_back(*x);
    // Elevation stops short of the poles, where the view's up direction would be lost.
    constexpr double kMaxElevation = 89.0;
    if (v.size() != a.size() || (v.size() != 3 && v.size() != 6) || !(v[2] >= sliderLow[3]) ||
        !(v[2] <= sliderHigh[3]) || !(std::abs(v[1]) <= kMaxElevation) || !std::isfinite(v[0])) {
        fail("BAD VIEW: expected view AZIMUTH ELEVATION ZOOM [CX CY CZ], ELEVATION -89..89, ZOOM " +
             number(sliderLow[3]) + ".." + number(sliderHigh[3]));
        return;
    }
    // A centre the model's own places could not reach shows nothing (and 1e300 overflows).
    if (v.size() == 6 &&
        !(std::max({std::abs(v[3]), std::abs(v[4]), std::abs(v[5])}) <= acsynt::kModelMaxLength)) {
        fail("BAD VIEW: the centre must lie within 1E6 model units of the origin, as the model does");
        return;
    }
    core_.azimuth = wrapDegrees(v[0]);
    core_.elevation = v[1];
    core_.zoom = v[2];
    if (v.size() == 6)
        core_.viewCentre = glm::dvec3(v[3], v[4], v[5]);
    else
        core_.viewCentre.reset();
    updateViews();
    drawScreen();
}

void Session::undoRedoKey(bool back) {
    extraLines_.emplace_back(core_.input->history().size(), back ? "undo" : "redo");
    if (back)
        undo();
    else
        redo();
}

bool Session::typing() const {
    return core_.awaiting != Awaiting::Nothing || !source_.stringEcho().text.empty();
}

void Session::toggleHelp() {
    help_ = !help_;
    drawHelp();
}

void Session::drawHelp() {
    std::vector<Element> e;
    if (help_) {
        static const char* const lines[] = {
            "KEYS AND MOUSE   (F1 OR H SHOWS AND HIDES THIS, ESCAPE HIDES IT)",
            "LEFT CLICK: A MENU ROW, A PAD BUTTON, A PICK ON A SURFACE",
            "LEFT DRAG IN A VIEW: ROTATE THE 3D VIEW (ACROSS: AZIMUTH, UP/DOWN: ELEVATION)",
            "WHEEL IN A VIEW: ZOOM",
            "MIDDLE DRAG OR SHIFT + LEFT DRAG IN A VIEW: PAN",
            "SLIDERS (DRAG, LIVE): U, W THE MARKER IN THE PATCH; ROTATE, ZOOM THE VIEWS",
            "CTRL+Z / CTRL+Y: UNDO / REDO",
            "TYPING FILLS A PROMPT: ENTER ACCEPTS, BACKSPACE EDITS, ESCAPE CANCELS",
            "F2..F12: MENU ITEM 2..12"};
        const PixelBox& g = layout_.geometry;
        const double unit = 1.0 / mapping_->pixelsPerNpc;
        std::size_t longest = 1;
        for (const char* line : lines) longest = std::max(longest, std::strlen(line));
        const double row = std::max(8.0, 0.04 * (g.y1 - g.y0));
        const PixelBox box{g.x0 + 0.04 * (g.x1 - g.x0), g.y0 + 0.06 * (g.y1 - g.y0),
                           g.x1 - 0.04 * (g.x1 - g.x0),
                           g.y0 + 0.06 * (g.y1 - g.y0) + row * (std::size(lines) + 1)};
        auto corners = outline(box);
        corners.pop_back();
        e = {viewIndex(0), addNamesToSet({structures::lineName}),
             IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)},
             colourAttr(ElementType::InteriorColour, {0.08, 0.1, 0.2}), fillArea3(corners),
             colourAttr(ElementType::PolylineColour, {0.6, 0.75, 1.0}), polyline3(outline(box)),
             // Stroke characters are about as wide as tall: the longest line fits the box.
             RealAttribute{ElementType::CharacterHeight,
                           std::min(0.45 * row, (box.x1 - box.x0 - 16) / longest) * unit},
             AlignmentAttribute{ElementType::TextAlignment, 1, 3}};
        for (std::size_t i = 0; i < std::size(lines); ++i) {
            e.push_back(
                colourAttr(ElementType::TextColour, i == 0 ? glm::dvec3(1, 1, 0.55) : glm::dvec3(0.9)));
            e.push_back(textAt(npc({box.x0 + 8, box.y0 + row * (i + 1)}), lines[i]));
        }
    }
    rewriteStructure(phigs_.store(), structures::help, e);
}

}  // namespace acsynt
