#pragma once

#include "phigs/input/InputDevice.h"
#include "phigs/view/ColourMappingTable.h"
#include "phigs/view/PrimitiveLimits.h"

#include <glm/vec2.hpp>

#include <string_view>
#include <vector>

namespace phigs {

/// The workstation types this implementation knows: Hardcopy is the PNG of the raster picture
/// (phigs_vk); PdfFile, SvgFile and EpsFile are the vector hardcopies (phigs_hardcopy).
enum class WorkstationType { OffscreenImage, Window, Hardcopy, PdfFile, SvgFile, EpsFile };

/// True for a value of WorkstationType (a number taken from outside, such as the C binding's).
bool isWorkstationType(WorkstationType type);

/// PHIGS workstation categories.
enum class WorkstationCategory { Output, OutIn };
/// PHIGS workstation classes: what the display surface is made of.
enum class WorkstationClass { Vector, Raster, Other };
/// PHIGS deferral modes: as soon as possible, before next interaction globally / locally, at
/// some time, when the application asks (UPDATE WORKSTATION).
enum class DeferralMode { Asap, Bnig, Bnil, Asti, Wait };
/// PHIGS modification modes: no immediate visual effect, update without regeneration, use quick
/// update methods.
enum class ModificationMode { Nive, Uwor, Uqum };
/// Dynamic modification accepted: a change needs an implicit regeneration, shows immediately,
/// or can be simulated.
enum class Dynamics { Irg, Imm, Cbs };

/// The workstation description table: what a type can do (INQUIRE ... FACILITIES).
struct WorkstationDescription {
    WorkstationType type = WorkstationType::OffscreenImage;
    WorkstationCategory category = WorkstationCategory::Output;
    glm::dvec2 displaySize{1024, 768};  ///< display space in device coordinates (pixels; points for vectors)
    int viewTableSize = 32;
    int colourTableSize = 256;
    int bundleTableSize = 32;
    int lightTableSize = 16;
    int depthCueTableSize = 8;
    int colourMappingTableSize = ColourMappingTable::kCapacity;  ///< entries 0 (TRUE) and up
    std::vector<int> hlhsrModes{0, 1};                           ///< 0 none, 1 z-buffer
    int interiorStyles = 5;
    /// Line and marker types and hatch styles (1 .. N), line and edge widths and marker sizes in
    /// device coordinates; the traversal draws what they allow (phigs/view/PrimitiveLimits.h).
    PrimitiveLimits primitives;
    WorkstationClass workstationClass = WorkstationClass::Raster;
    int patternTableSize = 32;
    /// Character heights and expansion factors (0: continuous range).
    double minCharHeight = 1.0e-6, maxCharHeight = 1.0e6;
    double minCharExpansion = 0.01, maxCharExpansion = 100.0;
    int textFonts = 4;                          ///< fonts 1..textFonts, each in every precision (stroked)
    std::vector<int> colourModels{1, 2, 3, 4};  ///< RGB, CIELUV, HSV, HLS (ColourModels.h)
    /// PHIGS PLUS: polyline shading methods (1 none, 2 colour), interior shading methods (1 none,
    /// 2 colour, 3 dot product, 4 normal) and reflectance equations (1 none .. 4 ambient, diffuse
    /// and specular).
    std::vector<int> polylineShadingMethods{1, 2};
    std::vector<int> interiorShadingMethods{1, 2, 3, 4};
    std::vector<int> reflectanceEquations{1, 2, 3, 4};
    int displayPriorities = 0;  ///< 0: continuous
    DeferralMode defaultDeferral = DeferralMode::Asap;
    ModificationMode defaultModification = ModificationMode::Nive;
    /// Every change of a workstation attribute or of the posted networks re-traverses.
    Dynamics attributeDynamics = Dynamics::Irg, structureDynamics = Dynamics::Irg;
    std::vector<int> gdps3;  ///< GDP 3 identifiers drawn (each with the polyline attributes)
    std::vector<int> gdps;   ///< GDP identifiers drawn (each with the polyline attributes)
    std::vector<int> gses;   ///< GSE identifiers acted on
    /// The logical input devices of each class (an OUTIN type; none for an OUTPUT one).
    DeviceCounts inputDevices{0, 0, 0, 0, 0, 0};
    std::string_view name;
};

/// The description of a workstation type.
WorkstationDescription describeWorkstationType(WorkstationType type);

}  // namespace phigs
