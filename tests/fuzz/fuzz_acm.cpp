// libFuzzer target: an aircraft description (`.acm`) as READ_MODEL reads it: parsed, written and
// read back to the same text, then lofted (every component, its mirror and its patch list). The
// documented failures are ModelFileError only; anything else escaping is a finding.
#include "FuzzSupport.h"
#include "acsynt/Model.h"
#include "acsynt/ModelFile.h"

#include <sstream>

namespace {

std::string written(const acsynt::AircraftDescription& description) {
    std::ostringstream out;
    acsynt::writeAircraftDescription(out, description);
    return out.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(fuzz::text(data, size));
    acsynt::AircraftDescription description;
    try {
        description = acsynt::parseAircraftDescription(in, "fuzz.acm");
    } catch (const acsynt::ModelFileError&) {
        return 0;
    }
    const std::string text = written(description);
    std::istringstream back(text);
    fuzz::check(written(acsynt::parseAircraftDescription(back, "written.acm")) == text,
                "acm write/read round trip");
    try {
        const acsynt::Model model = acsynt::buildModel(description, "fuzz.acm");
        fuzz::check(model.patchCount() > 0, "a lofted model has patches");
    } catch (const acsynt::ModelFileError&) {
    }
    return 0;
}
