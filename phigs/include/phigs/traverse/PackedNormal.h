#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace phigs {

/// A unit normal in four bytes: octahedral coordinates, 16 bits each (the direction within
/// 1e-4 radians, enough to shade with; the exact surface stays with the item for picking).
/// Axis directions and the zero vector come back exactly.
class PackedNormal {
public:
    PackedNormal() = default;
    /// Packs the direction of `n`, of any finite length; zero, or a NaN or infinite component,
    /// packs as zero.
    PackedNormal(const glm::vec3& n) {  // NOLINT(google-explicit-constructor): stored as one
        const float largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
        if (!(largest > 0.0f) || !std::isfinite(largest) || std::isnan(n.x) || std::isnan(n.y) ||
            std::isnan(n.z)) {
            x_ = y_ = kZero;
            return;
        }
        // Scaled by the largest component first, so that the sum below cannot overflow.
        const glm::vec3 m = n / largest;
        const float l1 = std::abs(m.x) + std::abs(m.y) + std::abs(m.z);
        float x = m.x / l1, y = m.y / l1;
        if (n.z < 0.0f) fold(x, y);
        x_ = quantize(x), y_ = quantize(y);
    }

    /// The unit direction (or zero).
    glm::vec3 unpacked() const {
        if (x_ == kZero) return glm::vec3(0.0f);
        float x = float(x_) / kScale, y = float(y_) / kScale;
        const float z = 1.0f - std::abs(x) - std::abs(y);
        if (z < 0.0f) fold(x, y);
        return glm::normalize(glm::vec3(x, y, z));
    }

    friend bool operator==(PackedNormal a, PackedNormal b) { return a.x_ == b.x_ && a.y_ == b.y_; }

private:
    static constexpr float kScale = 32767.0f;
    /// Below every quantized value: marks the zero vector.
    static constexpr std::int16_t kZero = std::numeric_limits<std::int16_t>::min();
    static float signOf(float v) { return v < 0.0f ? -1.0f : 1.0f; }
    /// The octahedron's lower half folded over its upper one (its own inverse).
    static void fold(float& x, float& y) {
        const float fx = (1.0f - std::abs(y)) * signOf(x), fy = (1.0f - std::abs(x)) * signOf(y);
        x = fx, y = fy;
    }
    static std::int16_t quantize(float v) {
        return static_cast<std::int16_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * kScale));
    }

    std::int16_t x_ = kZero, y_ = kZero;
};

}  // namespace phigs
