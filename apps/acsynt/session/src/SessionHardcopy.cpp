// FILE > HARDCOPY and the `hardcopy FILE` directive: the geometry area (one or four views) as a
// PDF, SVG or EPS file through a vector hardcopy workstation showing the same structures.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "phigs/hardcopy/VectorOutput.h"

#include <algorithm>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

namespace {

/// The hardcopy workstation's identifier: open only while a hardcopy is written.
constexpr int kHardcopyWorkstation = 2;

/// Closes the hardcopy workstation however the writing ends (close() to see its errors).
class OpenWorkstation {
public:
    OpenWorkstation(Phigs& phigs, int id, WorkstationType type, const OutputConnection& connection)
        : phigs_(phigs), id_(id), workstation_(phigs.openWorkstation(id, type, connection)) {}
    ~OpenWorkstation() {
        try {
            close();
        } catch (...) {
            // the error that ended the writing is the one reported
        }
    }
    void close() {
        if (open_) {
            open_ = false;
            phigs_.closeWorkstation(id_);
        }
    }
    OpenWorkstation(const OpenWorkstation&) = delete;
    OpenWorkstation& operator=(const OpenWorkstation&) = delete;
    Workstation& operator*() { return workstation_; }

private:
    Phigs& phigs_;
    int id_;
    Workstation& workstation_;
    bool open_ = true;
};

/// The screen's tables that the geometry uses: views, lights, colours and the HLHSR mode.
void copyTables(const WorkstationTables& from, Workstation& to) {
    for (int index : from.views.definedIndices())
        if (index > 0) to.setViewRepresentation(index, from.views.get(index));
    // A light's colour as it was given: an indexed one keeps following the colour table.
    for (const auto& [index, light] : from.lights)
        to.setLightSourceRepresentation(index, light, from.givenLightColour(index));
    for (int index : from.colours.definedIndices())
        to.setColourRepresentation(index, from.colours.get(index));
    to.setHlhsrMode(from.hlhsrMode);
}

/// Maps the NPC box [lo, hi] onto the middle of the display surface, keeping its shape.
void frame(Workstation& ws, glm::dvec3 lo, glm::dvec3 hi) {
    const glm::dvec2 display = ws.description().displaySize;
    const glm::dvec2 size(hi.x - lo.x, hi.y - lo.y);
    const double scale = std::min(display.x / size.x, display.y / size.y);
    const glm::dvec2 used = size * scale, offset = (display - used) / 2.0;
    ws.setWorkstationWindow(lo, hi);
    ws.setWorkstationViewport({offset.x, offset.y, 0}, {offset.x + used.x, offset.y + used.y, 1});
}

}  // namespace

void Session::writeHardcopy(const std::string& name) {
    if (!core_.settings.vectorHardcopies) {
        fail("HARDCOPIES ARE OFF IN THIS SESSION");
        return;
    }
    const std::filesystem::path path = outputPath(name);
    const hardcopy::VectorFormat format = hardcopy::vectorFormatForFile(path);  // invalid_argument
    // The geometry area and a pixel round it inside the screen, so that its frame is drawn whole.
    const PixelBox& g = layout_.geometry;
    const PixelBox area{std::max(g.x0 - 1, 0.0), std::max(g.y0 - 1, 0.0),
                        std::min(g.x1 + 1, double(layout_.width)),
                        std::min(g.y1 + 1, double(layout_.height))};
    // What the screen sizes in pixels (line widths, markers) keeps its size relative to the views.
    hardcopy::VectorSettings vector;
    const glm::dvec2 pageSize = vector.page.pageSize();
    vector.page.nominalPixel = std::min(pageSize.x / (area.x1 - area.x0), pageSize.y / (area.y1 - area.y0));
    vector.options.surfaces =
        core_.style.shaded ? hardcopy::SurfaceDrawing::Shaded : hardcopy::SurfaceDrawing::HiddenLine;
    OutputConnection connection;
    connection.identifier = path.string();
    connection.settings = vector;
    OpenWorkstation paper(phigs_, kHardcopyWorkstation, hardcopy::workstationTypeOf(format), connection);
    picture();  // the screen's views and model structures up to date
    copyTables(core_.workstation->tables(), *paper);
    frame(*paper, npc({area.x0, area.y1}, 0), npc({area.x1, area.y0}, 1));
    (*paper).postStructure(structures::geometry, 0.5);
    (*paper).postStructure(structures::legend, 0.85);  // the error map's colour key, when shown
    if (beforeHardcopy_) beforeHardcopy_();
    (*paper).present();  // std::runtime_error naming the file when it cannot be written
    paper.close();
    hardcopies_.push_back(path);
    core_.log.push_back("hardcopy " + path.string());
    say(std::string(hardcopy::vectorFormatName(format)) + " HARDCOPY OF " +
        (core_.fourViews ? "FOUR VIEWS" : "THE VIEW") + " WRITTEN TO " + path.string());
}

}  // namespace acsynt
