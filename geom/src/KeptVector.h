#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace geom::detail {

/// A std::vector whose storage the thread keeps when it is destroyed, for the next one made: a
/// reduction's large scratch arrays (hundreds of KiB on long curves) are then not handed back to
/// the system at the end of a call and faulted in anew by the next (glibc trims its heap once
/// 128 KiB lie free at the top; a page fault costs more than evaluating the samples on it).
/// Each thread keeps at most kKeptCount arrays of one element type, kKeptBytes in all.
template <class T>
class KeptVector : public std::vector<T> {
public:
    KeptVector() : std::vector<T>(pool().take()) {}
    explicit KeptVector(std::size_t n) : KeptVector() { this->resize(n); }
    KeptVector(std::size_t n, const T& value) : KeptVector() { this->assign(n, value); }
    KeptVector(const std::vector<T>& other) : KeptVector() { this->assign(other.begin(), other.end()); }
    KeptVector(const KeptVector& other) : KeptVector() { this->assign(other.begin(), other.end()); }
    KeptVector(KeptVector&& other) noexcept : std::vector<T>(std::move(other)) {}
    KeptVector& operator=(const KeptVector& other) {
        this->assign(other.begin(), other.end());
        return *this;
    }
    KeptVector& operator=(const std::vector<T>& other) {
        this->assign(other.begin(), other.end());
        return *this;
    }
    KeptVector& operator=(KeptVector&& other) noexcept {
        std::vector<T>::swap(other);
        return *this;
    }
    ~KeptVector() { pool().give(std::move(static_cast<std::vector<T>&>(*this))); }

private:
    static constexpr std::size_t kKeptCount = 32, kKeptBytes = std::size_t(16) << 20;

    struct Pool {
        std::vector<std::vector<T>> kept;
        std::size_t bytes = 0;

        std::vector<T> take() {
            if (kept.empty()) return {};
            std::vector<T> v = std::move(kept.back());
            kept.pop_back();
            bytes -= v.capacity() * sizeof(T);
            return v;
        }
        void give(std::vector<T>&& v) {
            const std::size_t size = v.capacity() * sizeof(T);
            if (size == 0 || kept.size() >= kKeptCount || bytes + size > kKeptBytes) return;
            v.clear();
            bytes += size;
            kept.push_back(std::move(v));
        }
    };
    static Pool& pool() {
        thread_local Pool p;
        return p;
    }
};

}  // namespace geom::detail
