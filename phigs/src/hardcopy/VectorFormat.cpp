#include "phigs/hardcopy/VectorFormat.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

namespace phigs::hardcopy {

VectorFormat vectorFormatForFile(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".pdf") return VectorFormat::Pdf;
    if (extension == ".svg") return VectorFormat::Svg;
    if (extension == ".eps") return VectorFormat::Eps;
    throw std::invalid_argument("vector hardcopy: " + file.string() +
                                ": the name must end in .pdf, .svg or .eps");
}

std::optional<VectorFormat> vectorFormatOf(WorkstationType type) {
    switch (type) {
        case WorkstationType::PdfFile:
            return VectorFormat::Pdf;
        case WorkstationType::SvgFile:
            return VectorFormat::Svg;
        case WorkstationType::EpsFile:
            return VectorFormat::Eps;
        case WorkstationType::OffscreenImage:
        case WorkstationType::Window:
        case WorkstationType::Hardcopy:
            break;
    }
    return std::nullopt;
}

WorkstationType workstationTypeOf(VectorFormat format) {
    switch (format) {
        case VectorFormat::Pdf:
            return WorkstationType::PdfFile;
        case VectorFormat::Svg:
            return WorkstationType::SvgFile;
        case VectorFormat::Eps:
            return WorkstationType::EpsFile;
    }
    throw std::invalid_argument("vector hardcopy: unknown format " + std::to_string(int(format)));
}

std::string_view vectorFormatName(VectorFormat format) {
    switch (format) {
        case VectorFormat::Pdf:
            return "PDF";
        case VectorFormat::Svg:
            return "SVG";
        case VectorFormat::Eps:
            return "EPS";
    }
    return "?";
}

}  // namespace phigs::hardcopy
