// libFuzzer target: a `.crv` curve file as LOAD_CURVE reads it. A file the parser accepts must
// write and read back to the same model (the writer promises an exact round trip), and its parts
// must interpolate or be refused with a GeometryError.
#include "FuzzSupport.h"
#include "geom/CurveFile.h"

#include <sstream>

namespace {

bool sameModel(const geom::CurveModel& a, const geom::CurveModel& b) {
    if (a.parts.size() != b.parts.size()) return false;
    for (std::size_t i = 0; i < a.parts.size(); ++i) {
        const geom::CurvePart &p = a.parts[i], &q = b.parts[i];
        if (p.name != q.name || p.points != q.points || p.continuities != q.continuities ||
            p.constraints != q.constraints)
            return false;
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(fuzz::text(data, size));
    geom::CurveModel model;
    try {
        model = geom::parseCurveFile(in, "fuzz.crv");
    } catch (const geom::CurveFileError&) {
        return 0;
    }
    std::ostringstream written;
    geom::writeCurveFile(written, model);  // a throw here is a finding: the parser accepted it
    std::istringstream back(written.str());
    fuzz::check(sameModel(model, geom::parseCurveFile(back, "written.crv")), "crv write/read round trip");
    try {
        const std::vector<geom::Curve> curves = geom::interpolateModel(model);
        fuzz::check(curves.size() == model.parts.size(), "one curve per part");
    } catch (const geom::GeometryError&) {
    }
    return 0;
}
