// The benchmark's peer: the same scene traced by Intel Embree 3 on the CPU, the way a user
// who wanted the fastest CPU ray caster would write it. Compiled only when libembree3 is
// found (CLRENDER_BENCH_HAVE_EMBREE).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "shared/clr_types.h"

namespace clr::bench {

class EmbreePeer {
public:
    // Builds the scene's BVH (RTC_BUILD_QUALITY_HIGH). Throws std::runtime_error on an
    // Embree error.
    EmbreePeer(const Scene& scene, const ClrCamera& camera);
    ~EmbreePeer();
    EmbreePeer(const EmbreePeer&) = delete;
    EmbreePeer& operator=(const EmbreePeer&) = delete;

    double build_ms() const { return build_ms_; }  // device, geometry and BVH build

    // Traces one frame of the camera's primary rays (and in a lit scene their shadow rays) on
    // every hardware thread; returns its wall time in ms.
    double trace_frame();

    // The object id of every pixel of the last frame (bench_scenes.h), rows from the top.
    const std::vector<std::uint32_t>& ids() const { return ids_; }
    // The last frame's colours, RGB bytes, rows from the top: each id's colour (bench_scenes.h),
    // lit by the sun in a lit scene as clrender lights it.
    const std::vector<std::uint8_t>& rgb() const { return rgb_; }

private:
    struct State;  // Embree handles and the callbacks' data, kept out of this header
    std::unique_ptr<State> state_;
    double build_ms_ = 0;
    std::vector<std::uint32_t> ids_;
    std::vector<std::uint8_t> rgb_;
};

// "Embree 3.13.5", for the report.
std::string embree_version();

}  // namespace clr::bench
