// A small 3-vector for host-side geometry. Double precision by default: the host flattens
// the scene and runs the reference renderer in double, and converts to float only when it
// fills device structs.
#pragma once

#include <cmath>
#include <limits>

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

// Whether v . v is computed without overflow or underflow, so that the plain formulas below
// are exact to the last bit as they always were. Outside that range (components beyond about
// 1e150 or below about 1e-150) the vector is first scaled by a power of two.
template <typename T>
bool squares_safely(const Vec3T<T>& v) {
    const T square = dot(v, v);
    return square >= std::numeric_limits<T>::min() && square <= std::numeric_limits<T>::max();
}

// v as m * 2^exponent, with m's largest component in [0.5, 1): its square can neither
// overflow nor underflow (std::ldexp by a power of two is exact). Zero and non-finite
// vectors are returned as they are.
template <typename T>
Vec3T<T> unit_order(const Vec3T<T>& v, int& exponent) {
    exponent = 0;
    const T largest = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    if (!(largest > 0) || !std::isfinite(largest)) return v;
    std::frexp(largest, &exponent);
    return {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
}

// |v| for any finite v: 1e-300 and 1e300 long vectors are measured right, where the plain
// sqrt(v.v) underflows to 0 or overflows to inf.
template <typename T>
T length(const Vec3T<T>& v) {
    if (squares_safely(v)) return std::sqrt(dot(v, v));
    int exponent = 0;
    const Vec3T<T> m = unit_order(v, exponent);
    return std::ldexp(std::sqrt(dot(m, m)), exponent);
}

// v / |v| for any finite non-zero v, whatever its length: a direction's length does not
// matter, so a scene may give `up` as [0, 1e-300, 0] or [0, 1e300, 0].
template <typename T>
Vec3T<T> normalize(const Vec3T<T>& v) {
    if (squares_safely(v)) return v / std::sqrt(dot(v, v));
    int exponent = 0;
    const Vec3T<T> m = unit_order(v, exponent);
    return m / std::sqrt(dot(m, m));
}

// Component-wise product, used for colours.
template <typename T>
constexpr Vec3T<T> hadamard(const Vec3T<T>& a, const Vec3T<T>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }

using Vec3 = Vec3T<double>;

}  // namespace clr
