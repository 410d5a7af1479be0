#pragma once

#include "acsynt/Model.h"
#include "phigs/input/InputTypes.h"
#include "phigs/store/StructureStore.h"

#include <optional>
#include <vector>

namespace acsynt {

/// How the model is drawn.
struct DisplayStyle {
    bool shaded = true;           ///< shaded surfaces (else iso-line wireframe)
    bool hull = false;            ///< control hulls on
    int onlyComponent = -1;       ///< draw only this component (DEFINE POINT), -1: all
    int colourfulComponent = -1;  ///< draw this component with each patch in its own colour
    int highlightComponent = -1;  ///< with highlightPatch: the patch drawn in the highlight colour
    int highlightPatch = 0;
    int errorMapComponent = -1;  ///< hidden: its error colour map is drawn instead
};

/// The PHIGS structures of one model (ACSYNT's acs_root, component acs_id, patch patch_strid
/// and hull_id): a root that executes one structure per component, which sets the component's
/// attributes and executes one structure per patch; each patch structure holds the patch as a
/// NON-UNIFORM B-SPLINE SURFACE (its 8 + 8 local knots and 4 x 4 hull, so picks report the
/// component's own (u, w)) under pick id = patch number, and its boundary as polylines.
namespace structures {
constexpr int geometry = 10;    ///< posted: one view index + the model per view
constexpr int menu = 20;        ///< posted: the menu panel
constexpr int pad = 21;         ///< posted: the pointer-valuator buttons (pickable)
constexpr int message = 23;     ///< posted: the title and message line
constexpr int sliders = 24;     ///< posted: 24-27, the sliders of valuators 1-4
constexpr int legend = 28;      ///< posted: the error map's colour legend
constexpr int help = 29;        ///< posted: the key and mouse help overlay (F1, H)
constexpr int modelRoot = 100;  ///< the model (acs_root)
constexpr int mapped = 101;     ///< mapped curves of the model
constexpr int overlay = 102;    ///< marker, tangents, placed curve, projection lines
constexpr int errorMap = 103;   ///< the reduction error colour map
/// Name-set names: what the pick filter lets through.
constexpr int pickableName = 1;  ///< model surfaces
constexpr int lineName = 2;      ///< lines drawn over them (not pickable)
constexpr int buttonName = 3;    ///< pad buttons
inline int component(int index) {
    return 1000 + index;
}
inline int hull(int index) {
    return 2000 + index;
}
inline int patch(int index, int number) {
    return 100000 * (index + 1) + number;
}
}  // namespace structures

/// A component and patch recognised in a pick path.
struct PickedPatch {
    int component = -1;
    int patch = 0;  ///< patch number (1-based), 0 when only the component is known
};

/// Builds and restyles the structures of a model in the store.
class ModelPicture {
public:
    explicit ModelPicture(phigs::StructureStore& store) : store_(store) {}

    /// (Re)writes every structure of the model.
    void build(const Model& model, const DisplayStyle& style);
    /// Rewrites the root and the component structures only (patches unchanged).
    void restyle(const Model& model, const DisplayStyle& style);
    /// Deletes the structures of the model last built.
    void clear();
    /// The component and patch a pick path went through, if any.
    static std::optional<PickedPatch> fromPath(const std::vector<phigs::PickPathItem>& path);
    /// The colour DEFINE POINT gives patch `number` (a fixed cycle of distinct colours).
    static glm::dvec3 patchColour(int number);

private:
    void writeComponent(const Model& model, int index, const DisplayStyle& style);
    phigs::StructureStore& store_;
    std::vector<int> built_;  ///< structure ids written by build()
};

/// Replaces the contents of structure `id` with `elements` (creating it when missing), all or
/// nothing: an element the store would refuse (phigs::Error -202 or -201), or a structure left
/// open (6), throws before the structure is touched.
void rewriteStructure(phigs::StructureStore& store, int id, const std::vector<phigs::Element>& elements);

}  // namespace acsynt
