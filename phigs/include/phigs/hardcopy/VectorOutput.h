#pragma once

#include "phigs/hardcopy/VectorWorkstation.h"
#include "phigs/ws/OutputRegistry.h"
#include "phigs/ws/WorkstationOutput.h"

#include <cstdint>
#include <filesystem>

namespace phigs::hardcopy {

/// A vector hardcopy's page, surface drawing and page mode: what a program may hand to OPEN
/// WORKSTATION in OutputConnection::settings for the PDF, SVG and EPS types.
struct VectorSettings {
    PageSetup page;
    VectorOptions options;
    PageMode mode = PageMode::Replace;
};

/// The output of a PDF, SVG or EPS workstation: every presented picture drawn into the file
/// (a new file, or a new page in Document mode); on close the picture gets drawn where the file
/// was never presented or the picture changed since.
class VectorOutput : public WorkstationOutput {
public:
    VectorOutput(std::filesystem::path file, VectorFormat format, const VectorSettings& settings);

    bool present(const DrawList& picture) override;
    /// The page in points.
    DrawableSize drawableSize() const override;
    void close(const DrawList& picture) override;
    const VectorWorkstation& file() const { return file_; }

private:
    VectorWorkstation file_;
    glm::dvec2 page_;
    bool presented_ = false;
    std::uint64_t presentedGeneration_ = 0;  ///< of the last picture presented
};

/// Adds the PdfFile, SvgFile and EpsFile outputs to `registry`: the connection identifier is the
/// file name (required: ConnectionRefused, error 50); OutputConnection::settings may hold
/// VectorSettings (default: A4 landscape, one picture per file).
void registerOutputs(OutputRegistry& registry);

}  // namespace phigs::hardcopy
