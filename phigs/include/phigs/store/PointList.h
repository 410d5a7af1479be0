#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace phigs {

class ElementArena;

/// The points of an output primitive, read as a span: its own heap copy while the element is a
/// free value, a view of its structure's point pool once the store holds the element.
class PointList {
public:
    PointList() = default;
    PointList(std::span<const glm::dvec3> points) { assign(points); }
    PointList(const std::vector<glm::dvec3>& points) : PointList(std::span<const glm::dvec3>(points)) {}
    PointList(std::initializer_list<glm::dvec3> points)
        : PointList(std::span<const glm::dvec3>(points.begin(), points.size())) {}
    /// Copies own their points, whatever the original held.
    PointList(const PointList& other) : PointList(other.span()) {}
    PointList(PointList&& other) noexcept : data_(other.data_), size_(other.size_), owned_(other.owned_) {
        other.data_ = nullptr, other.size_ = 0, other.owned_ = false;
    }
    PointList& operator=(const PointList& other) {
        if (this != &other) {
            PointList copy(other);
            swap(copy);
        }
        return *this;
    }
    PointList& operator=(PointList&& other) noexcept {
        PointList gone(std::move(other));
        swap(gone);
        return *this;
    }
    ~PointList() { release(); }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const glm::dvec3* data() const { return data_; }
    const glm::dvec3* begin() const { return data_; }
    const glm::dvec3* end() const { return data_ + size_; }
    const glm::dvec3& operator[](std::size_t i) const { return data_[i]; }
    const glm::dvec3& front() const { return data_[0]; }
    const glm::dvec3& back() const { return data_[size_ - 1]; }
    std::span<const glm::dvec3> span() const { return {data_, size_}; }
    operator std::span<const glm::dvec3>() const { return span(); }
    std::vector<glm::dvec3> toVector() const { return {begin(), end()}; }
    /// Whether the list holds its own heap copy (a free value) rather than viewing a pool.
    bool ownsPoints() const { return owned_; }

    bool operator==(const PointList& other) const;

    void swap(PointList& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(owned_, other.owned_);
    }

private:
    friend class ElementArena;
    void assign(std::span<const glm::dvec3> points);
    void release() noexcept;
    /// Frees an own copy and views `count` points at `at` (a pool's) instead.
    void view(glm::dvec3* at, std::uint32_t count) noexcept {
        release();
        data_ = at, size_ = count, owned_ = false;
    }

    glm::dvec3* data_ = nullptr;
    std::uint32_t size_ = 0;
    bool owned_ = false;
};

}  // namespace phigs
