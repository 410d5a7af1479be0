#pragma once

#include "geom/Curve.h"
#include "geom/GeometryError.h"
#include "geom/Interpolate.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace geom {

/// One closed curve part of a `.crv` file: data points (last == first), continuities and tangents.
struct CurvePart {
    std::string name;
    std::vector<glm::dvec3> points;
    std::vector<Continuity> continuities;
    std::vector<glm::dvec3> constraints;  ///< 2 per C0 point, 1 per C1 point, in point order
    std::size_t line = 0;                 ///< the file line of its point count (0: not from a file)
};

/// A `.crv` curve model (the ACSYNT curve-mapping thesis, §7.2, Table 1): every part of one file, mapped
/// together.
struct CurveModel {
    std::vector<CurvePart> parts;
};

/// Thrown for a malformed `.crv` file; the message is "<file>:<line>: <reason>".
class CurveFileError : public GeometryError {
public:
    CurveFileError(std::string file, std::size_t line, const std::string& reason);
    const std::string& file() const { return file_; }
    std::size_t line() const { return line_; }

private:
    std::string file_;
    std::size_t line_;
};

/// Limits of a `.crv` file, each refused with CurveFileError at the line that breaks it (the
/// part's interpolation is a dense solve, so points per part bound its time and memory).
inline constexpr std::size_t kCurveFileMaxPointsPerPart = 1000;
inline constexpr std::size_t kCurveFileMaxParts = 256;
inline constexpr std::size_t kCurveFileMaxPoints = 10000;  ///< all parts together
inline constexpr std::size_t kCurveFileMaxLineLength = 1024;

/// Reads a `.crv` file; throws CurveFileError (file, line, reason) for a missing file or a
/// directory, a wrong heading, a wrong count, a bad number or continuity, a part that does not
/// close, a control character, or a limit above broken.
CurveModel readCurveFile(const std::filesystem::path& path);
/// Parses `.crv` text; `source` names it in error messages.
CurveModel parseCurveFile(std::istream& in, const std::string& source);

/// Writes the model in the thesis's layout (exact round trip: 17 significant digits). Throws
/// GeometryError for a part that would not read back (unclosed, wrong constraint count).
void writeCurveFile(const std::filesystem::path& path, const CurveModel& model);
void writeCurveFile(std::ostream& out, const CurveModel& model);

/// The cubic through a part (closed, with its continuities and constraints).
Curve interpolatePart(const CurvePart& part,
                      Parameterization parameterization = Parameterization::ChordLength);
/// interpolatePart for every part, in order.
std::vector<Curve> interpolateModel(const CurveModel& model,
                                    Parameterization parameterization = Parameterization::ChordLength);

}  // namespace geom
