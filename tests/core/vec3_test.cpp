// length() and normalize() for vectors of any finite length: a direction's length does not
// matter, so 1e-300 and 1e300 long vectors must give the same unit vector as a short one.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "core/vec3.h"

namespace clr {
namespace {

void expect_unit_along(const Vec3& unit, const Vec3& expected, const std::string& what) {
    EXPECT_NEAR(unit.x, expected.x, 1e-15) << what;
    EXPECT_NEAR(unit.y, expected.y, 1e-15) << what;
    EXPECT_NEAR(unit.z, expected.z, 1e-15) << what;
}

TEST(Vec3, NormalizeHandlesAnyFiniteLength) {
    const Vec3 direction{3, -4, 12};  // length 13
    const Vec3 expected = direction / 13.0;
    for (double scale : {1e-320, 1e-300, 1e-160, 1e-20, 1.0, 1e20, 1e160, 1e300, 1e307}) {
        expect_unit_along(normalize(direction * scale), expected, "scale " + std::to_string(scale));
    }
}

TEST(Vec3, NormalizeOfTheLargestAndSmallestDoubles) {
    expect_unit_along(normalize(Vec3{DBL_MAX, DBL_MAX, 0}), Vec3{1, 1, 0} / std::sqrt(2.0), "DBL_MAX");
    expect_unit_along(normalize(Vec3{0, -DBL_TRUE_MIN, 0}), Vec3{0, -1, 0}, "smallest subnormal");
}

TEST(Vec3, LengthHandlesAnyFiniteLength) {
    for (double scale : {1e-300, 1e-160, 1.0, 1e160, 1e300}) {
        const double measured = length(Vec3{3, -4, 12} * scale);
        EXPECT_NEAR(measured / (13 * scale), 1.0, 1e-15) << "scale " << scale;
    }
}

// The scaling is by a power of two, so ordinary vectors get exactly the plain formula's bits:
// images rendered before stay byte-identical.
TEST(Vec3, OrdinaryVectorsGiveThePlainFormulasBits) {
    for (const Vec3& v : {Vec3{0.3, 1.7, -2.9}, Vec3{1e-5, 3e4, 7}, Vec3{-123.456, 0, 1e-3}}) {
        const double plain_length = std::sqrt(dot(v, v));
        EXPECT_EQ(length(v), plain_length);
        EXPECT_EQ(normalize(v), v / plain_length);
    }
}

}  // namespace
}  // namespace clr
