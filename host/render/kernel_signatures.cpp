#include "render/kernel_signatures.h"

namespace clr {
namespace {

template <typename Signature>
KernelDeclaration declaration(const Signature& signature) {
    return {signature.kernel_name(), signature.params()};
}

}  // namespace

std::vector<KernelDeclaration> kernel_declarations() {
    return {declaration(kRenderPackets), declaration(kRender), declaration(kRaygen),
            declaration(kIntersect),     declaration(kShade),  declaration(kStructLayout)};
}

}  // namespace clr
