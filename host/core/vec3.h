// A small 3-vector for host-side geometry. Double precision by default: the host flattens
// the scene and runs the reference renderer in double, and converts to float only when it
// fills device structs.
#pragma once

#include <cmath>

namespace clr {

template <typename T>
struct Vec3T {
    T x = 0, y = 0, z = 0;

    constexpr Vec3T() = default;
    constexpr Vec3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}

    constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3T operator+(const Vec3T& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3T operator-(const Vec3T& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3T operator-() const { return {-x, -y, -z}; }
    constexpr Vec3T operator*(T s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3T operator/(T s) const { return {x / s, y / s, z / s}; }
    constexpr bool operator==(const Vec3T& o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(const Vec3T& o) const { return !(*this == o); }
};

template <typename T>
constexpr Vec3T<T> operator*(T s, const Vec3T<T>& v) { return v * s; }

template <typename T>
constexpr T dot(const Vec3T<T>& a, const Vec3T<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

template <typename T>
constexpr Vec3T<T> cross(const Vec3T<T>& a, const Vec3T<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <typename T>
T length(const Vec3T<T>& v) { return std::sqrt(dot(v, v)); }

template <typename T>
Vec3T<T> normalize(const Vec3T<T>& v) { return v / length(v); }

// Component-wise product, used for colours.
template <typename T>
constexpr Vec3T<T> hadamard(const Vec3T<T>& a, const Vec3T<T>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

using Vec3 = Vec3T<double>;

}  // namespace clr
