#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/vec2.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace phigs::render {

/// One glyph of a stroke font: pen strokes in font units (x right, y up, baseline at 0) and advance.
struct StrokeGlyph {
    std::vector<std::vector<glm::dvec2>> strokes;
    double left = 0.0, right = 0.0;  ///< horizontal extent; the advance is right - left
};

/// A Hershey stroke font read from a .jhf file (Debian package hershey-fonts-data), glyphs for
/// ASCII 32..126 in file order. Cap height is 21 font units (Hershey's -12..9 rows).
class StrokeFont {
public:
    static constexpr double kCapHeight = 21.0;
    static constexpr double kTop = 25.0;     ///< above the baseline, accents included
    static constexpr double kBottom = -7.0;  ///< descenders

    /// Reads a .jhf file; throws std::runtime_error naming the file and line when it is malformed.
    static StrokeFont load(const std::filesystem::path& file);
    /// The font for a PHIGS text font index: 1 (and any other) Roman simplex, 2 Roman duplex,
    /// 3 Roman triplex, 4 script; looked up under PHIGS_HERSHEY_DIR or /usr/share/hershey-fonts.
    static const StrokeFont& forIndex(int font);
    /// The file forIndex reads for `font`; throws std::runtime_error naming PHIGS_HERSHEY_DIR
    /// where that is set and has no such file (the Debian package would not help there).
    static std::filesystem::path fileFor(int font);

    /// The glyph of a character; characters outside 32..126 map to '?'.
    const StrokeGlyph& glyph(char c) const;

private:
    std::vector<StrokeGlyph> glyphs_;
};

/// Lays out a string with PHIGS text attributes into line strips in the text plane, in the same
/// units as style.height (x along the text plane's first axis, y along its second).
std::vector<std::vector<glm::dvec2>> layoutText(const StrokeFont& font, const std::string& text,
                                                const TextStyle& style);

/// A string's text extent rectangle (the union of the character bodies, Hershey rows kBottom..kTop)
/// and its concatenation point (along the path, where the next character would start; across it,
/// on the alignment line), in text local coordinates: the units of style.height, alignment
/// applied, before the up vector turns them (INQUIRE TEXT EXTENT).
struct TextExtent {
    glm::dvec2 min{0.0}, max{0.0};
    glm::dvec2 concatenation{0.0};
};
TextExtent textExtent(const StrokeFont& font, const std::string& text, const TextStyle& style);

}  // namespace phigs::render
