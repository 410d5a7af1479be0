// FOUR_VIEWS frames a model of any proportions: each axis view shows the whole model.
#include "SessionTestSupport.h"

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace test_session_framing {

using session_test::Driver;

namespace {

/// A model file of one fuselage `length` long and `width` wide (its sections as ellipses from
/// nose to tail), with, where span > 0, a wing of that span.
std::string slenderModel(double length, double width, double height, double span) {
    std::string text =
        "acsynt-model 1\nmodel slender\n\ncomponent fuselage fuselage\n  points 16\n  sections 7\n";
    const double stations[] = {0.0, 0.05, 0.15, 0.4, 0.7, 0.9, 1.0};
    for (double f : stations) {
        const double r = f == 0.0 ? 0.0 : (f == 1.0 ? 0.3 : 1.0);
        text += "  station mid " + std::to_string(f * length) + " " + std::to_string(r * width / 2) + " " +
                std::to_string(r * height / 2) + " " + std::to_string(r * height / 2) + " 0 2\n";
    }
    text += "end\n";
    if (span > 0)
        text +=
            "\ncomponent wing right_wing\n  points 13\n  sections 5\n  mirror left_wing\n  airfoil 0012 "
            "0012\n  position " +
            std::to_string(0.4 * length) + " 0 0\n  root_chord " + std::to_string(0.1 * length + 1) +
            "\n  taper 0.5\n  span " + std::to_string(span) + "\n  sweep 10\n  twist 0\nend\n";
    return text;
}

}  // namespace

TEST_CASE("FOUR_VIEWS: every axis view shows the whole of a slender or flat model") {
    // A fuselage 100 long and 2 wide showed 45 of its 50 half-length in the plan and side views
    // (0.9 of the bounding sphere): nose and tail were cut off.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto dir = session_test::outputDirectory("framing");
    std::filesystem::create_directories(dir);
    for (int member = 0; member < 6; ++member) {
        const double length = 20.0 + 180.0 * unit(rng), width = 1.0 + 3.0 * unit(rng);
        const double span = member % 2 == 0 ? 0.0 : length * (0.5 + 1.5 * unit(rng));
        const auto file = dir / ("slender_" + std::to_string(member) + ".acm");
        std::ofstream(file) << slenderModel(length, width, 0.8 * width, span);
        Driver d("framing");
        d.run({"choice FILE", "choice READ_MODEL", "string " + file.string(), "choice RETURN", "choice VIEW",
               "choice FOUR_VIEWS", "choice RETURN"});
        REQUIRE(d.session.models().size() == 1);
        INFO("member " << member << ": length " << length << ", width " << width << ", span " << span);
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const acsynt::Component& c : d.session.models().current().components)
            for (const glm::dvec3& p : c.surface.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        for (int v = 1; v <= 3; ++v) {
            const acsynt::PixelBox box = d.session.layout().viewBox(v, true);
            for (int corner = 0; corner < 8; ++corner) {
                const glm::dvec3 p((corner & 1 ? hi : lo).x, (corner & 2 ? hi : lo).y,
                                   (corner & 4 ? hi : lo).z);
                const glm::dvec2 pixel = d.session.pixelOf(p, v);
                INFO("view " << v << ", corner " << corner << " at pixel " << pixel.x << ", " << pixel.y);
                CHECK(box.contains(pixel));
            }
        }
    }
}

}  // namespace test_session_framing
