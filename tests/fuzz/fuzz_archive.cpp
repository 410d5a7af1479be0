// libFuzzer target: a PHIGS archive file. The input is opened as an archive and retrieved into
// the store, an element is inserted, every structure is posted to a model workstation (no GPU)
// and traversed into its draw list, and each draw item is described as the Vulkan backend would
// before uploading (render::describeItem, meshVertices, meshIndices). Refusals are phigs::Error;
// what the writer writes from an accepted archive must read back to the same text.
//
// Mutations rarely keep the FNV-1a checksum of the END line right, which would stop nearly every
// input at the check, so the target rewrites the checksum of the last END line first: a finding's
// input file reproduces with this target, not necessarily with OPEN ARCHIVE FILE alone.
#include "FuzzSupport.h"
#include "phigs/Phigs.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/traverse/WorkstationMapping.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <string_view>

namespace {

std::uint64_t fnv1a(std::string_view bytes) {
    std::uint64_t hash = 1469598103934665603ull;
    for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

bool space(char c) {
    return c == ' ' || c == '\n' || c == '\t' || c == '\r';
}

/// The text with the checksum after the last "END <count>" replaced by the right one.
std::string withChecksum(std::string text) {
    std::size_t end = text.rfind("END");
    while (end != std::string::npos && end > 0 && !space(text[end - 1])) end = text.rfind("END", end - 1);
    if (end == std::string::npos || end == 0) return text;
    std::size_t at = end + 3;
    while (at < text.size() && space(text[at])) ++at;
    while (at < text.size() && !space(text[at])) ++at;  // the structure count
    char sum[20];
    std::snprintf(sum, sizeof sum, " %016llx\n", static_cast<unsigned long long>(fnv1a(text.substr(0, end))));
    return text.substr(0, at) + sum;
}

/// What the renderer does with a draw list before it touches the GPU.
void describe(const phigs::DrawList& list) {
    const phigs::WorkstationMapping mapping(list, 1024, 768);
    const glm::dmat4 npcToPixels = glm::dmat4(glm::dvec4(512, 0, 0, 0), glm::dvec4(0, 384, 0, 0),
                                              glm::dvec4(0, 0, 1, 0), glm::dvec4(512, 384, 0, 1)) *
                                   mapping.npcToClip;
    const phigs::DrawView defaultView;
    for (const phigs::DrawItem& item : list.items) {
        if (const auto* mesh = phigs::primitiveIf<phigs::DrawMesh>(item.primitive)) {
            if (!mesh->mesh) continue;
            phigs::render::meshVertices(*mesh->mesh);
            phigs::render::meshIndices(*mesh->mesh);
            continue;
        }
        // The renderer refuses an item whose view the list does not have; so does this.
        if (item.viewIndex() < 0 || (item.viewIndex() >= int(list.views.size()) && !list.views.empty()))
            continue;
        const phigs::DrawView& view =
            list.views.empty() ? defaultView : list.views[std::size_t(item.viewIndex())];
        phigs::render::describeItem(item, npcToPixels * view.mapping * view.orientation);
    }
}

/// What the writer writes from what the reader read, the reader must read back to the same text.
void roundTrip(const std::string& text) {
    std::map<int, std::vector<phigs::Element>> contents;
    try {
        contents = phigs::ArchiveFile::decode(text, "fuzz.phar", nullptr);
    } catch (const phigs::Error&) {
        return;
    }
    const std::string once = phigs::ArchiveFile::encode(contents);
    fuzz::check(phigs::ArchiveFile::encode(phigs::ArchiveFile::decode(once, "encoded.phar", nullptr)) == once,
                "archive encode/decode round trip");
}

void exercise(phigs::Phigs& phigs, const std::filesystem::path& file) {
    phigs.openArchiveFile(1, file);
    const std::vector<int> ids = phigs.archiveContents(1);
    phigs.retrieveAllStructures(1);
    phigs.closeArchiveFile(1);

    auto& store = phigs.store();
    store.openStructure(ids.empty() ? 1 : ids.front());
    store.insert(phigs::polyline3({{0, 0, 0}, {1, 1, 0}}));
    try {
        store.insert(phigs::executeStructure(ids.empty() ? 2 : ids.back()));  // may close a cycle
    } catch (const phigs::Error&) {
    }
    store.closeStructure();

    phigs::Workstation& ws = phigs.openWorkstation(1, phigs::WorkstationType::OffscreenImage);
    for (int id : ids) ws.postStructure(id, 0.5);
    describe(ws.display());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path file = fuzz::scratch() / "input.phar";
    {
        const std::string text = withChecksum(fuzz::text(data, size));
        roundTrip(text);
        std::ofstream(file, std::ios::binary).write(text.data(), std::streamsize(text.size()));
    }
    phigs::Phigs phigs;
    phigs.open();
    try {
        exercise(phigs, file);
    } catch (const phigs::Error&) {
    }
    return 0;
}
