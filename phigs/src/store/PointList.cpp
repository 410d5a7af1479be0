#include "phigs/store/PointList.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace phigs {

void PointList::assign(std::span<const glm::dvec3> points) {
    if (points.size() > std::numeric_limits<std::uint32_t>::max() / sizeof(glm::dvec3))
        throw std::length_error("PointList: more points than one primitive may hold");
    if (points.empty()) return;
    data_ = new glm::dvec3[points.size()];
    std::copy(points.begin(), points.end(), data_);
    size_ = static_cast<std::uint32_t>(points.size());
    owned_ = true;
}

void PointList::release() noexcept {
    if (owned_) delete[] data_;
    data_ = nullptr, size_ = 0, owned_ = false;
}

bool PointList::operator==(const PointList& other) const {
    return std::equal(begin(), end(), other.begin(), other.end());
}

}  // namespace phigs
