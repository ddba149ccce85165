#include "support/obj_text.h"

namespace clr::testing {

std::string grid_obj_text(int cells) {
    std::string text = "mtllib grid.mtl\nusemtl green\n";
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) text += "v " + std::to_string(i * 0.25) + " 0 " + std::to_string(-j * 0.5) + "\n";
    text += "vn 0 1 0\n";
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            const int a = j * (cells + 1) + i + 1, b = a + 1, c = a + cells + 2, d = a + cells + 1;
            text += "f " + std::to_string(a) + "//1 " + std::to_string(b) + "//1 " + std::to_string(c) + "//1\n";
            text += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
        }
    return text;
}

}  // namespace clr::testing
