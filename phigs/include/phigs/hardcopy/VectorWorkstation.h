#pragma once

#include "phigs/hardcopy/PageSetup.h"
#include "phigs/hardcopy/VectorDescriber.h"
#include "phigs/hardcopy/VectorFormat.h"
#include "phigs/hardcopy/VectorOptions.h"
#include "phigs/traverse/DrawList.h"

#include <filesystem>
#include <memory>

namespace phigs::hardcopy {

/// Whether a vector hardcopy keeps one picture or collects pages.
enum class PageMode {
    Replace,  ///< every update rewrites the file with that one picture
    Document  ///< every update adds a page; the file is complete on close() (PDF only)
};

/// A vector hardcopy workstation: draws draw lists into a PDF, SVG or encapsulated PostScript file
/// through cairo, every primitive a vector path (no raster image). Files appear whole: each is
/// written under a temporary name and renamed when done.
class VectorWorkstation {
public:
    /// Throws std::invalid_argument for a document of a format other than PDF.
    VectorWorkstation(std::filesystem::path file, VectorFormat format, PageSetup page = {},
                      VectorOptions options = {}, PageMode mode = PageMode::Replace);
    ~VectorWorkstation();
    VectorWorkstation(const VectorWorkstation&) = delete;
    VectorWorkstation& operator=(const VectorWorkstation&) = delete;

    /// Draws the list: a new file (Replace) or a new page (Document). Throws std::runtime_error
    /// naming the file when cairo cannot write it.
    void update(const DrawList& list);
    /// Completes the document (Document mode) and stops accepting updates.
    void close();

    const std::filesystem::path& file() const { return file_; }
    VectorFormat format() const { return format_; }
    int pages() const { return pages_; }
    /// The page of the last update, without its operations: cairo holds them once painted.
    const VectorPicture& lastPicture() const { return picture_; }
    /// How many paint operations the last update made.
    std::size_t lastOperations() const { return operations_; }
    const DescribeStats& lastStats() const { return stats_; }

private:
    struct Surface;

    std::filesystem::path file_;
    VectorFormat format_;
    PageSetup page_;
    VectorOptions options_;
    PageMode mode_;
    std::unique_ptr<Surface> document_;  ///< the open document (Document mode)
    int pages_ = 0;
    bool closed_ = false;
    VectorPicture picture_;
    std::size_t operations_ = 0;
    DescribeStats stats_;
};

}  // namespace phigs::hardcopy
