// A small 3-vector for host-side geometry, in double precision: the host flattens
// the scene and runs the reference renderer in double, and converts to float only when it
// fills device structs.
#pragma once

#include <cmath>
#include <limits>

namespace clr {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(const Vec3& o) const { return !(*this == o); }
};

constexpr Vec3 operator*(double s, const Vec3& v) { return v * s; }

constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Whether v . v is computed without overflow or underflow, so that the plain formulas below
// are exact to the last bit as they always were. Outside that range (components beyond about
// 1e150 or below about 1e-150) the vector is first scaled by a power of two.
inline bool squares_safely(const Vec3& v) {
    const double square = dot(v, v);
    return square >= std::numeric_limits<double>::min() && square <= std::numeric_limits<double>::max();
}

// v as m * 2^exponent, with m's largest component in [0.5, 1): its square can neither
// overflow nor underflow (std::ldexp by a power of two is exact). Zero and non-finite
// vectors are returned as they are.
inline Vec3 unit_order(const Vec3& v, int& exponent) {
    exponent = 0;
    const double largest = std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
    if (!(largest > 0) || !std::isfinite(largest)) return v;
    std::frexp(largest, &exponent);
    return {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
}

// |v| for any finite v: 1e-300 and 1e300 long vectors are measured right, where the plain
// sqrt(v.v) underflows to 0 or overflows to inf.
inline double length(const Vec3& v) {
    if (squares_safely(v)) return std::sqrt(dot(v, v));
    int exponent = 0;
    const Vec3 m = unit_order(v, exponent);
    return std::ldexp(std::sqrt(dot(m, m)), exponent);
}

// v / |v| for any finite non-zero v, whatever its length: a direction's length does not
// matter, so a scene may give `up` as [0, 1e-300, 0] or [0, 1e300, 0].
inline Vec3 normalize(const Vec3& v) {
    if (squares_safely(v)) return v / std::sqrt(dot(v, v));
    int exponent = 0;
    const Vec3 m = unit_order(v, exponent);
    return m / std::sqrt(dot(m, m));
}

}  // namespace clr
