#include "phigs/render/StrokeFont.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace phigs::render {

StrokeFont StrokeFont::load(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in)
        throw std::runtime_error("stroke font " + file.string() +
                                 ": cannot open (install the Debian package 'hershey-fonts-data')");
    StrokeFont font;
    std::string line, record;
    int lineNumber = 0;
    auto parse = [&](const std::string& r) {
        if (r.size() < 10)
            throw std::runtime_error("stroke font " + file.string() + " line " + std::to_string(lineNumber) +
                                     ": record too short");
        const int count = std::atoi(r.substr(5, 3).c_str());
        if (count < 1 || r.size() < std::size_t(8 + 2 * count))
            throw std::runtime_error("stroke font " + file.string() + " line " + std::to_string(lineNumber) +
                                     ": vertex count does not match the record");
        StrokeGlyph g;
        g.left = r[8] - 'R';
        g.right = r[9] - 'R';
        bool penUp = true;
        for (int i = 1; i < count; ++i) {
            const char cx = r[8 + 2 * i], cy = r[9 + 2 * i];
            if (cx == ' ' && cy == 'R') {
                penUp = true;
                continue;
            }
            if (penUp) g.strokes.emplace_back();
            penUp = false;
            // Hershey rows grow downward with the baseline at row 9.
            g.strokes.back().push_back({double(cx - 'R'), 9.0 - double(cy - 'R')});
        }
        font.glyphs_.push_back(std::move(g));
    };
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        // A record longer than 72 characters continues on the next line; a new record starts with
        // its 5-character number and 3-character count.
        if (!record.empty()) {
            const int count = std::atoi(record.substr(5, 3).c_str());
            if (record.size() < std::size_t(8 + 2 * count)) {
                record += line;
                if (record.size() >= std::size_t(8 + 2 * count)) {
                    parse(record);
                    record.clear();
                }
                continue;
            }
        }
        record = line;
        const int count = std::atoi(record.substr(5, std::min<std::size_t>(3, record.size() - 5)).c_str());
        if (record.size() >= std::size_t(8 + 2 * count)) {
            parse(record);
            record.clear();
        }
    }
    if (!record.empty()) parse(record);
    if (font.glyphs_.size() < 95)
        throw std::runtime_error("stroke font " + file.string() + ": only " +
                                 std::to_string(font.glyphs_.size()) +
                                 " glyphs, expected 95 (ASCII 32..126)");
    return font;
}

std::filesystem::path StrokeFont::fileFor(int font) {
    const char* names[] = {"futural.jhf", "futuram.jhf", "timesr.jhf", "scripts.jhf"};
    const char* name = names[(font >= 1 && font <= 4 ? font : 1) - 1];
    const char* dir = std::getenv("PHIGS_HERSHEY_DIR");
    if (!dir) return std::filesystem::path("/usr/share/hershey-fonts") / name;
    const std::filesystem::path file = std::filesystem::path(dir) / name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw std::runtime_error("stroke font " + file.string() + ": not found in PHIGS_HERSHEY_DIR (" + dir +
                                 "); unset it to use /usr/share/hershey-fonts");
    return file;
}

const StrokeFont& StrokeFont::forIndex(int font) {
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<StrokeFont>> fonts;
    const int index = (font >= 1 && font <= 4) ? font : 1;
    std::lock_guard lock(mutex);
    auto& slot = fonts[index];
    if (!slot) slot = std::make_unique<StrokeFont>(load(fileFor(index)));
    return *slot;
}

const StrokeGlyph& StrokeFont::glyph(char c) const {
    const int i = static_cast<unsigned char>(c) - 32;
    return glyphs_[(i >= 0 && i < 95) ? i : '?' - 32];
}

namespace {

struct Placed {
    const StrokeGlyph* glyph;
    glm::dvec2 origin;
};

/// Glyph origins along the path in text-local units (before the up-vector rotation), the body
/// box, the alignment shift and where the next character would go.
struct Layout {
    std::vector<Placed> placed;
    double scale = 1.0, xScale = 1.0;
    double minX = 0.0, maxX = 0.0, bottomY = 0.0, topY = 0.0;
    glm::dvec2 shift{0.0};
    glm::dvec2 next{0.0};
};

Layout layout(const StrokeFont& font, const std::string& text, const TextStyle& style) {
    Layout l;
    l.scale = style.height / StrokeFont::kCapHeight;
    l.xScale = l.scale * style.expansion;
    const double gap = style.spacing * style.height;
    const bool vertical = style.path == TextPath::Up || style.path == TextPath::Down;
    const double unit = l.scale;
    const double cell = (StrokeFont::kTop - StrokeFont::kBottom) * unit;
    // The bodies' reach along the path: with negative spacing a later character may end before an
    // earlier one, so the extent is the bodies' union, not the pen's travel.
    double pen = 0.0, widest = 0.0;
    double lowX = 0.0, highX = 0.0, lowBase = 0.0, highBase = 0.0;
    for (char c : text) {
        const StrokeGlyph& g = font.glyph(c);
        const double width = (g.right - g.left) * l.xScale;
        widest = std::max(widest, width);
        const bool first = l.placed.empty();
        if (vertical) {
            const double y = style.path == TextPath::Up ? pen : -pen;
            l.placed.push_back({&g, {-0.5 * width - g.left * l.xScale, y}});
            lowBase = first ? y : std::min(lowBase, y), highBase = first ? y : std::max(highBase, y);
            pen += cell + gap;
        } else {
            const double x = style.path == TextPath::Right ? pen : -pen - width;
            l.placed.push_back({&g, {x - g.left * l.xScale, 0.0}});
            lowX = first ? x : std::min(lowX, x), highX = first ? x + width : std::max(highX, x + width);
            pen += width + gap;
        }
    }

    // Alignment: shift so the alignment point lies at the text position.
    HorizontalAlignment h = style.horizontal;
    VerticalAlignment v = style.vertical;
    if (h == HorizontalAlignment::Normal)
        h = vertical
                ? HorizontalAlignment::Centre
                : (style.path == TextPath::Left ? HorizontalAlignment::Right : HorizontalAlignment::Left);
    if (v == VerticalAlignment::Normal)
        v = style.path == TextPath::Down ? VerticalAlignment::Top : VerticalAlignment::Base;
    double capY, baseY;
    if (vertical) {
        l.minX = -0.5 * widest;
        l.maxX = 0.5 * widest;
        l.topY = highBase + StrokeFont::kTop * unit;
        capY = highBase + style.height;
        baseY = lowBase;
        l.bottomY = lowBase + StrokeFont::kBottom * unit;
    } else {
        l.minX = lowX;
        l.maxX = highX;
        l.topY = StrokeFont::kTop * unit;
        capY = style.height;
        baseY = 0.0;
        l.bottomY = StrokeFont::kBottom * unit;
    }
    const double halfY = 0.5 * (capY + baseY);
    l.shift.x = h == HorizontalAlignment::Left    ? -l.minX
                : h == HorizontalAlignment::Right ? -l.maxX
                                                  : -0.5 * (l.minX + l.maxX);
    l.shift.y = v == VerticalAlignment::Top    ? -l.topY
                : v == VerticalAlignment::Cap  ? -capY
                : v == VerticalAlignment::Half ? -halfY
                : v == VerticalAlignment::Base ? -baseY
                                               : -l.bottomY;
    const double along = text.empty() ? 0.0 : pen;
    l.next = style.path == TextPath::Right  ? glm::dvec2(along, 0.0)
             : style.path == TextPath::Left ? glm::dvec2(-along, 0.0)
             : style.path == TextPath::Up   ? glm::dvec2(0.0, along)
                                            : glm::dvec2(0.0, -along);
    return l;
}

}  // namespace

std::vector<std::vector<glm::dvec2>> layoutText(const StrokeFont& font, const std::string& text,
                                                const TextStyle& style) {
    const Layout l = layout(font, text, style);
    // Rotate so that local +y follows the up vector; the baseline is the up vector turned clockwise.
    glm::dvec2 up = style.upVector;
    const double length = std::hypot(up.x, up.y);
    up = length > 0 ? up / length : glm::dvec2(0, 1);
    const glm::dvec2 baseline(up.y, -up.x);

    std::vector<std::vector<glm::dvec2>> strips;
    for (const Placed& p : l.placed)
        for (const auto& stroke : p.glyph->strokes) {
            std::vector<glm::dvec2> strip;
            strip.reserve(stroke.size());
            for (const glm::dvec2& q : stroke) {
                const glm::dvec2 local(p.origin.x + q.x * l.xScale + l.shift.x,
                                       p.origin.y + q.y * l.scale + l.shift.y);
                strip.push_back(baseline * local.x + up * local.y);
            }
            strips.push_back(std::move(strip));
        }
    return strips;
}

TextExtent textExtent(const StrokeFont& font, const std::string& text, const TextStyle& style) {
    const Layout l = layout(font, text, style);
    if (text.empty()) return {l.shift, l.shift, l.shift};
    // The concatenation point stays on the alignment line (a second string aligned alike continues
    // the first's line or column); along the path it is where the next character would go.
    const bool vertical = style.path == TextPath::Up || style.path == TextPath::Down;
    const glm::dvec2 next = l.next + l.shift;
    return {glm::dvec2(l.minX, l.bottomY) + l.shift, glm::dvec2(l.maxX, l.topY) + l.shift,
            vertical ? glm::dvec2(0.0, next.y) : glm::dvec2(next.x, 0.0)};
}

}  // namespace phigs::render
