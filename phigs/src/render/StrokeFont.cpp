#include "phigs/render/StrokeFont.h"

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

const StrokeFont& StrokeFont::forIndex(int font) {
    static std::mutex mutex;
    static std::map<int, std::unique_ptr<StrokeFont>> fonts;
    const char* names[] = {"futural.jhf", "futuram.jhf", "timesr.jhf", "scripts.jhf"};
    const int index = (font >= 1 && font <= 4) ? font : 1;
    std::lock_guard lock(mutex);
    auto& slot = fonts[index];
    if (!slot) {
        const char* dir = std::getenv("PHIGS_HERSHEY_DIR");
        const std::filesystem::path base = dir ? dir : "/usr/share/hershey-fonts";
        slot = std::make_unique<StrokeFont>(load(base / names[index - 1]));
    }
    return *slot;
}

const StrokeGlyph& StrokeFont::glyph(char c) const {
    const int i = static_cast<unsigned char>(c) - 32;
    return glyphs_[(i >= 0 && i < 95) ? i : '?' - 32];
}

std::vector<std::vector<glm::dvec2>> layoutText(const StrokeFont& font, const std::string& text,
                                                const TextStyle& style) {
    const double scale = style.height / StrokeFont::kCapHeight;
    const double xScale = scale * style.expansion;
    const double gap = style.spacing * style.height;
    const bool vertical = style.path == TextPath::Up || style.path == TextPath::Down;

    // Place each glyph's origin along the path in text-local units (before the up-vector rotation).
    struct Placed {
        const StrokeGlyph* glyph;
        glm::dvec2 origin;
    };
    const double unit = scale;
    const double cell = (StrokeFont::kTop - StrokeFont::kBottom) * unit;
    std::vector<Placed> placed;
    double pen = 0.0, widest = 0.0;
    for (char c : text) {
        const StrokeGlyph& g = font.glyph(c);
        const double width = (g.right - g.left) * xScale;
        widest = std::max(widest, width);
        if (vertical) {
            const double y = style.path == TextPath::Up ? pen : -pen;
            placed.push_back({&g, {-0.5 * width - g.left * xScale, y}});
            pen += cell + gap;
        } else {
            const double x = style.path == TextPath::Right ? pen : -pen - width;
            placed.push_back({&g, {x - g.left * xScale, 0.0}});
            pen += width + gap;
        }
    }
    const double extent = text.empty() ? 0.0 : pen - gap;
    const double lastBase = text.empty() ? 0.0 : (style.path == TextPath::Up ? 1 : -1) * (pen - cell - gap);

    // Alignment: shift so the alignment point lies at the text position.
    HorizontalAlignment h = style.horizontal;
    VerticalAlignment v = style.vertical;
    if (h == HorizontalAlignment::Normal)
        h = vertical
                ? HorizontalAlignment::Centre
                : (style.path == TextPath::Left ? HorizontalAlignment::Right : HorizontalAlignment::Left);
    if (v == VerticalAlignment::Normal)
        v = style.path == TextPath::Down ? VerticalAlignment::Top : VerticalAlignment::Base;
    double minX, maxX, topY, capY, baseY, bottomY;
    if (vertical) {
        minX = -0.5 * widest;
        maxX = 0.5 * widest;
        const double highest = style.path == TextPath::Up ? lastBase : 0.0;
        const double lowest = style.path == TextPath::Up ? 0.0 : lastBase;
        topY = highest + StrokeFont::kTop * unit;
        capY = highest + style.height;
        baseY = lowest;
        bottomY = lowest + StrokeFont::kBottom * unit;
    } else {
        minX = style.path == TextPath::Right ? 0.0 : -extent;
        maxX = style.path == TextPath::Right ? extent : 0.0;
        topY = StrokeFont::kTop * unit;
        capY = style.height;
        baseY = 0.0;
        bottomY = StrokeFont::kBottom * unit;
    }
    const double halfY = 0.5 * (capY + baseY);
    const double dx = h == HorizontalAlignment::Left    ? -minX
                      : h == HorizontalAlignment::Right ? -maxX
                                                        : -0.5 * (minX + maxX);
    const double dy = v == VerticalAlignment::Top    ? -topY
                      : v == VerticalAlignment::Cap  ? -capY
                      : v == VerticalAlignment::Half ? -halfY
                      : v == VerticalAlignment::Base ? -baseY
                                                     : -bottomY;

    // Rotate so that local +y follows the up vector; the baseline is the up vector turned clockwise.
    glm::dvec2 up = style.upVector;
    const double length = std::hypot(up.x, up.y);
    up = length > 0 ? up / length : glm::dvec2(0, 1);
    const glm::dvec2 baseline(up.y, -up.x);

    std::vector<std::vector<glm::dvec2>> strips;
    for (const Placed& p : placed)
        for (const auto& stroke : p.glyph->strokes) {
            std::vector<glm::dvec2> strip;
            strip.reserve(stroke.size());
            for (const glm::dvec2& q : stroke) {
                const glm::dvec2 local(p.origin.x + q.x * xScale + dx, p.origin.y + q.y * scale + dy);
                strip.push_back(baseline * local.x + up * local.y);
            }
            strips.push_back(std::move(strip));
        }
    return strips;
}

}  // namespace phigs::render
