#pragma once

#include "phigs/input/InputDevice.h"

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
    std::vector<int> hlhsrModes{0, 1};  ///< 0 none, 1 z-buffer
    int lineTypes = 4, markerTypes = 5, interiorStyles = 5;
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
