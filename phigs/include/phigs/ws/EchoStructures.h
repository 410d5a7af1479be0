#pragma once

#include "phigs/input/EchoLayout.h"
#include "phigs/store/StructureStore.h"
#include "phigs/traverse/WorkstationMapping.h"

#include <glm/vec3.hpp>

#include <string>

namespace phigs {

/// Colours (direct RGB) of the echo structures.
struct EchoStyle {
    glm::dvec3 box{0.22, 0.24, 0.30};
    glm::dvec3 current{0.95, 0.70, 0.15};  ///< the current alternative, the knob
    glm::dvec3 outline{0.75, 0.75, 0.80};
    glm::dvec3 text{1.0, 1.0, 1.0};
    glm::dvec3 currentText{0.0, 0.0, 0.0};
    glm::dvec3 track{0.35, 0.36, 0.42};
    double npcZ = 1.0;  ///< at the front of NPC space, over the picture
};

/// Replaces the contents of structure `structureId` with the choice panel drawn as PHIGS
/// elements: per alternative (pick id = its number) a solid box, the current one (1-based; 0:
/// none) highlighted, an outline and its name in Hershey stroke text, placed through view 0
/// (world = NPC) on the pixels of the panel's echo area on the surface `mapping` describes.
/// The application posts the structure on its workstation and rebuilds it when the current
/// alternative or the surface changes. Error 6 (nothing changes) while a structure is open.
void buildChoicePanel(StructureStore& store, int structureId, const ChoicePanel& panel, int current,
                      const WorkstationMapping& mapping, const EchoStyle& style = {});

/// Replaces the contents of structure `structureId` with the valuator slider: the track, the
/// knob at `value`, and "label: value" in stroke text above the track (horizontal sliders) or
/// beside it (vertical ones); placed and posted as buildChoicePanel says.
void buildValuatorSlider(StructureStore& store, int structureId, const ValuatorSlider& slider, double value,
                         const std::string& label, const WorkstationMapping& mapping,
                         const EchoStyle& style = {});

}  // namespace phigs
