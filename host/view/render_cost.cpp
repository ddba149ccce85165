#include "view/render_cost.h"

#include <algorithm>
#include <string>

namespace clr {

long long most_view_samples(const Scene& scene) {
    const long long own = static_cast<long long>(scene.width) * scene.height * scene.sampling.samples_per_pixel;
    return std::max(kViewerMostSamples, own);
}

void check_render_cost(const Scene& scene, const ViewCamera& view, const ViewQuery& query) {
    const int spp = view.sampling.samples_per_pixel;
    const long long samples = static_cast<long long>(view.width) * view.height * spp;
    const long long most = most_view_samples(scene);
    if (samples <= most) return;
    const long long pixels = static_cast<long long>(view.width) * view.height;
    const long long most_spp = most / pixels;
    const std::string frame = std::to_string(view.width) + "x" + std::to_string(view.height);
    std::string message = "size " + frame + " at spp " + std::to_string(spp) + " is " + std::to_string(samples) +
                          " samples; the viewer renders at most " + std::to_string(most) + " per frame (" +
                          (most_spp >= 1 ? "spp " + std::to_string(most_spp) + " at this size"
                                         : "a smaller size") +
                          "); clrender SCENE --size " + frame + " --spp " + std::to_string(spp) + " renders it";
    throw ParameterError(query.samples_per_pixel ? "spp" : "size", message);
}

}  // namespace clr
