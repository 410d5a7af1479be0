#include "phigs/hardcopy/VectorOutput.h"

#include "phigs/hardcopy/VectorFormat.h"

#include <cmath>
#include <memory>

namespace phigs::hardcopy {

VectorOutput::VectorOutput(std::filesystem::path file, VectorFormat format, const VectorSettings& settings)
    : file_(std::move(file), format, settings.page, settings.options, settings.mode),
      page_(settings.page.pageSize()) {
}

bool VectorOutput::present(const DrawList& picture) {
    file_.update(picture);  // std::runtime_error naming the file when cairo cannot write it
    presented_ = true;
    presentedGeneration_ = picture.generation;
    return true;
}

DrawableSize VectorOutput::drawableSize() const {
    return {static_cast<std::uint32_t>(std::lround(page_.x)),
            static_cast<std::uint32_t>(std::lround(page_.y))};
}

void VectorOutput::close(const DrawList& picture) {
    // Never written (no update, or each failed), or changed since (CLOSE WORKSTATION updates):
    // the last picture is written now (a document's last page), and a file that still cannot
    // be written is reported again (903), as the PNG type does.
    if (!presented_ || picture.generation != presentedGeneration_) file_.update(picture);
    file_.close();
}

void registerOutputs(OutputRegistry& registry) {
    for (VectorFormat format : {VectorFormat::Pdf, VectorFormat::Svg, VectorFormat::Eps})
        registry.add(workstationTypeOf(format), [format](Workstation&, const OutputConnection& connection) {
            if (connection.identifier.empty())
                throw ConnectionRefused(std::string("a ") + std::string(vectorFormatName(format)) +
                                        " hardcopy needs a file name as its connection identifier");
            const VectorSettings* given = std::any_cast<VectorSettings>(&connection.settings);
            return std::make_unique<VectorOutput>(connection.identifier, format,
                                                  given ? *given : VectorSettings{});
        });
}

}  // namespace phigs::hardcopy
