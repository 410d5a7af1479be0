#include "phigs/hardcopy/VectorWorkstation.h"

#include "CairoPainter.h"
#include "phigs/core/FileTarget.h"

#include <cairo-pdf.h>
#include <cairo-ps.h>
#include <cairo-svg.h>

#include <stdexcept>
#include <string>
#include <system_error>

namespace phigs::hardcopy {

/// One cairo file surface being written under the temporary name.
struct VectorWorkstation::Surface {
    Surface(const std::filesystem::path& file, VectorFormat format, glm::dvec2 size)
        : target(replacedFile(file)), temporary(target.string() + ".tmp") {
        if (const std::string why = notReplaceable(target); !why.empty())
            throw std::runtime_error("vector hardcopy: " + file.string() + " " + why);
        if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
        const std::string name = temporary.string();
        switch (format) {
            case VectorFormat::Pdf:
                surface = cairo_pdf_surface_create(name.c_str(), size.x, size.y);
                cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "PHIGS toolkit");
                break;
            case VectorFormat::Svg:
                surface = cairo_svg_surface_create(name.c_str(), size.x, size.y);
                cairo_svg_surface_restrict_to_version(surface, CAIRO_SVG_VERSION_1_1);
                cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PT);
                break;
            case VectorFormat::Eps:
                surface = cairo_ps_surface_create(name.c_str(), size.x, size.y);
                cairo_ps_surface_set_eps(surface, 1);
                break;
        }
        cairo = cairo_create(surface);
        try {
            check("cannot be opened");
        } catch (...) {
            release();
            throw;
        }
    }
    ~Surface() { release(); }

    void release() {
        if (cairo) cairo_destroy(cairo);
        if (surface) cairo_surface_destroy(surface);
        cairo = nullptr, surface = nullptr;
        std::error_code ignored;
        if (!finished) std::filesystem::remove(temporary, ignored);
    }

    void check(const char* what) const {
        cairo_status_t status = cairo_status(cairo);
        if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(surface);
        if (status != CAIRO_STATUS_SUCCESS)
            throw std::runtime_error("vector hardcopy: " + target.string() + " " + what + ": " +
                                     cairo_status_to_string(status));
    }

    /// Writes the rest of the file and gives it its name.
    void finish() {
        check("cannot be written");
        cairo_destroy(cairo);
        cairo = nullptr;
        cairo_surface_finish(surface);
        const cairo_status_t status = cairo_surface_status(surface);
        if (status != CAIRO_STATUS_SUCCESS)
            throw std::runtime_error("vector hardcopy: " + target.string() +
                                     " cannot be written: " + cairo_status_to_string(status));
        std::filesystem::rename(temporary, target);
        finished = true;
    }

    std::filesystem::path target, temporary;
    cairo_surface_t* surface = nullptr;
    cairo_t* cairo = nullptr;
    bool finished = false;
};

VectorWorkstation::VectorWorkstation(std::filesystem::path file, VectorFormat format, PageSetup page,
                                     VectorOptions options, PageMode mode)
    : file_(std::move(file)), format_(format), page_(page), options_(options), mode_(mode) {
    if (mode_ == PageMode::Document && format_ != VectorFormat::Pdf)
        throw std::invalid_argument("vector hardcopy: " + file_.string() +
                                    ": only PDF holds several pages, not " +
                                    std::string(vectorFormatName(format_)));
}

VectorWorkstation::~VectorWorkstation() {
    try {
        close();
    } catch (...) {
        // A destructor must not throw; close() explicitly to see write errors.
    }
}

void VectorWorkstation::update(const DrawList& list) {
    if (closed_) throw std::logic_error("VectorWorkstation::update: " + file_.string() + " is closed");
    picture_ = describePicture(list, page_, options_, &stats_);
    const glm::dvec2 size = picture_.pageSize;
    std::unique_ptr<Surface> single;
    Surface* target = nullptr;
    if (mode_ == PageMode::Document) {
        if (!document_) document_ = std::make_unique<Surface>(file_, format_, size);
        if (pages_ > 0) cairo_show_page(document_->cairo);
        cairo_pdf_surface_set_size(document_->surface, size.x, size.y);
        target = document_.get();
    } else {
        single = std::make_unique<Surface>(file_, format_, size);
        target = single.get();
    }
    operations_ = picture_.ops.size();
    CairoPainter(target->cairo, format_ == VectorFormat::Eps).paint(picture_);
    target->check("cannot be drawn");
    ++pages_;
    if (single) single->finish();
}

void VectorWorkstation::close() {
    if (closed_) return;
    closed_ = true;
    if (document_) document_->finish();
}

}  // namespace phigs::hardcopy
