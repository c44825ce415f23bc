// The media a ray travels through, innermost last: what Snell's law needs on both sides of a
// surface when refracting objects nest (glass in water, an air bubble in glass). A refracted ray
// that enters an object pushes it; one that leaves it removes it. Outside every object is
// vacuum, n = 1. An object made of separate faces (polygons of one material) is left through
// another face than it was entered by: leaving a face never entered removes the innermost
// medium of the same material.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace glint {

struct Material;

struct MediumCrossing;

class MediumStack {
public:
    // Vacuum. User-provided (not = default), so that a const stack needs no initialiser while
    // the unused entries stay unwritten.
    MediumStack() {}  // NOLINT(modernize-use-equals-default)
    // Copies the media in use only: a ray crosses few, and refracted rays copy the stack.
    MediumStack(const MediumStack& o) : size_(o.size_) {
        std::copy_n(o.entries_.begin(), size_, entries_.begin());
    }
    MediumStack& operator=(const MediumStack& o) {
        size_ = o.size_;
        std::copy_n(o.entries_.begin(), size_, entries_.begin());
        return *this;
    }

    // The index of the medium the ray travels in.
    float ior() const { return size_ > 0 ? entries_[size_ - 1].ior : 1.0f; }

    // Entering the object `primitive` of the given material and index. Deeper nesting than
    // kCapacity keeps the outer media only: a ray leaving the deepest objects then returns to
    // the last one kept.
    MediumCrossing enter(std::uint32_t primitive, const Material* material, float ior) const;
    // Leaving the object `primitive`: the ray passes into the innermost medium that remains.
    // Leaving an object never entered removes the innermost one of the same material, if any
    // (else the ray started inside it, and the stack stays as it is).
    MediumCrossing leave(std::uint32_t primitive, const Material* material, float ior) const;

    // enter(...).after and leave(...).after, copying the stack once.
    MediumStack entered(std::uint32_t primitive, const Material* material, float ior) const {
        MediumStack s = *this;
        if (s.size_ < kCapacity) s.entries_[s.size_++] = {primitive, ior, material};
        return s;
    }
    MediumStack left(std::uint32_t primitive, const Material* material) const {
        MediumStack s = *this;
        if (const int i = s.find(primitive, material); i >= 0) s.remove(i);
        return s;
    }

    // The index the ray passes into when it leaves the object `primitive`: leave(...).n2
    // without copying the stack.
    float ior_after_leaving(std::uint32_t primitive, const Material* material) const;

    int size() const { return size_; }
    // The material of the innermost medium; null in vacuum.
    const Material* innermost_material() const {
        return size_ > 0 ? entries_[size_ - 1].material : nullptr;
    }
    // The material of the medium `level` steps out from the innermost (0: the innermost), for
    // level < size().
    const Material* material_out(int level) const { return entries_[size_ - 1 - level].material; }

    static constexpr int kCapacity = 8;

private:
    struct Entry {
        std::uint32_t primitive;
        float ior;
        const Material* material;
    };
    void remove(int i);
    // The entry leaving `primitive` removes: its own, else the innermost of its material; -1.
    int find(std::uint32_t primitive, const Material* material) const {
        for (int i = size_ - 1; i >= 0; --i)
            if (entries_[i].primitive == primitive) return i;
        for (int i = size_ - 1; i >= 0; --i)
            if (entries_[i].material == material) return i;
        return -1;
    }
    std::array<Entry, kCapacity> entries_;  // the first size_ in use
    int size_ = 0;
};

// Outside every object: where eye rays start. One shared value, so that tracing a ray does not
// build an empty stack each time.
inline const MediumStack kVacuum;

// The indices of refraction on both sides of a surface a refracted ray crosses, and the media
// the refracted ray then travels through.
struct MediumCrossing {
    float n1, n2;  // incident side, transmitted side: Snell's eta = n1 / n2
    MediumStack after;
};

inline MediumCrossing MediumStack::enter(std::uint32_t primitive, const Material* material,
                                         float ior) const {
    return {this->ior(), ior, entered(primitive, material, ior)};
}

inline void MediumStack::remove(int i) {
    for (int j = i; j + 1 < size_; ++j) entries_[j] = entries_[j + 1];
    --size_;
}

inline float MediumStack::ior_after_leaving(std::uint32_t primitive,
                                            const Material* material) const {
    const int found = find(primitive, material);
    // The innermost medium that remains.
    for (int i = size_ - 1; i >= 0; --i)
        if (i != found) return entries_[i].ior;
    return 1.0f;
}

inline MediumCrossing MediumStack::leave(std::uint32_t primitive, const Material* material,
                                         float ior) const {
    MediumCrossing c{ior, 1.0f, left(primitive, material)};
    c.n2 = c.after.ior();
    return c;
}

}  // namespace glint
