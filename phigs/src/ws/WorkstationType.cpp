#include "phigs/ws/WorkstationType.h"

namespace phigs {

WorkstationDescription describeWorkstationType(WorkstationType type) {
    WorkstationDescription d;
    d.type = type;
    switch (type) {
        case WorkstationType::OffscreenImage:
            d.name = "offscreen image";
            break;
        case WorkstationType::Window:
            d.name = "window";
            d.category = WorkstationCategory::OutIn;
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
            break;
    }
    return d;
}

}  // namespace phigs
