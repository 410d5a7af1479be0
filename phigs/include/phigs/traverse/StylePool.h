#pragma once

// The resolved attribute records draw items share. A record type gains a field by adding it to
// its struct in core/Attributes.h (its defaulted operator== then compares it; the hashes below
// need not read it).

#include "phigs/core/Attributes.h"
#include "phigs/traverse/InternTable.h"

#include <bit>
#include <cstdint>

namespace phigs {

namespace detail {

/// A hash of a style's colour and one more number: enough to spread the records of a scene.
inline std::size_t styleHash(const glm::vec3& colour, std::uint64_t more) {
    std::uint64_t h = 1469598103934665603ull;
    for (float c : {colour.x, colour.y, colour.z, static_cast<float>(more)})
        h = (h ^ std::bit_cast<std::uint32_t>(c)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
}

struct LineStyleHash {
    std::size_t operator()(const LineStyle& s) const {
        return styleHash(s.colour,
                         static_cast<std::uint64_t>(s.type) * 977u + std::bit_cast<std::uint32_t>(s.width));
    }
};
struct MarkerStyleHash {
    std::size_t operator()(const MarkerStyle& s) const {
        return styleHash(s.colour,
                         static_cast<std::uint64_t>(s.type) * 977u + std::bit_cast<std::uint32_t>(s.scale));
    }
};
struct TextStyleHash {
    std::size_t operator()(const TextStyle& s) const {
        return styleHash(s.colour,
                         static_cast<std::uint64_t>(s.font) * 977u + std::bit_cast<std::uint64_t>(s.height));
    }
};
struct InteriorStyleHash {
    std::size_t operator()(const InteriorStyleSet& s) const {
        return styleHash(s.colour,
                         static_cast<std::uint64_t>(s.style) * 977u + static_cast<std::uint64_t>(s.shading));
    }
};
struct EdgeStyleHash {
    std::size_t operator()(const EdgeStyle& s) const {
        return styleHash(s.colour, static_cast<std::uint64_t>(s.type) * 977u + s.visible);
    }
};

}  // namespace detail

/// The interned style records of the draw items one traverser makes: one record per distinct
/// resolved style, at an address that stays while any draw segment holds the pool.
struct StylePool {
    InternTable<LineStyle, detail::LineStyleHash> lines;
    InternTable<MarkerStyle, detail::MarkerStyleHash> markers;
    InternTable<TextStyle, detail::TextStyleHash> texts;
    InternTable<InteriorStyleSet, detail::InteriorStyleHash> interiors;
    InternTable<EdgeStyle, detail::EdgeStyleHash> edges;

    std::size_t size() const {
        return lines.size() + markers.size() + texts.size() + interiors.size() + edges.size();
    }
};

}  // namespace phigs
