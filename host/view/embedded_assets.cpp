#include "view/embedded_assets.h"

namespace clr {

const EmbeddedAsset* find_viewer_asset(std::string_view path) {
    for (const EmbeddedAsset& asset : embedded_viewer_assets()) {
        if (asset.content().data() != nullptr && path == asset.path) return &asset;
    }
    return nullptr;
}

}  // namespace clr
