#include "phigs/ws/WorkstationType.h"

#include "phigs/store/Gdp.h"

namespace phigs {

bool isWorkstationType(WorkstationType type) {
    const int value = static_cast<int>(type);
    return value >= static_cast<int>(WorkstationType::OffscreenImage) &&
           value <= static_cast<int>(WorkstationType::EpsFile);
}

WorkstationDescription describeWorkstationType(WorkstationType type) {
    WorkstationDescription d;
    d.type = type;
    d.gdps3 = d.gdps = {gdp::Circle, gdp::ThreePointArc};  // traversal draws them for every output
    switch (type) {
        case WorkstationType::OffscreenImage:
            d.name = "offscreen image";
            d.category = WorkstationCategory::OutIn;  // its input comes from a script source
            d.inputDevices = DeviceCounts{};
            break;
        case WorkstationType::Window:
            d.name = "window";
            d.category = WorkstationCategory::OutIn;
            d.inputDevices = DeviceCounts{};
            break;
        case WorkstationType::Hardcopy:
            d.name = "hardcopy";
            d.displaySize = {3508, 2480};  // A4 landscape at 300 dpi
            break;
        case WorkstationType::PdfFile:
        case WorkstationType::SvgFile:
        case WorkstationType::EpsFile:
            d.name = type == WorkstationType::PdfFile   ? "PDF hardcopy"
                     : type == WorkstationType::SvgFile ? "SVG hardcopy"
                                                        : "EPS hardcopy";
            d.displaySize = {841.8898, 595.2756};  // A4 landscape in points: one device unit is 1/72 inch
            d.workstationClass = WorkstationClass::Vector;
            break;
    }
    return d;
}

}  // namespace phigs
