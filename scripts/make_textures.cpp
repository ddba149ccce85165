// Draws the demo scene's textures from code and writes them into a folder (argv[1], default
// scenes/demo): checker.png, cutout.png and backdrop.png through stb_image_write, and
// sign.ppm as ASCII PPM (P3) so that the demo also exercises that reader.
//
// All drawing is integer arithmetic, so every machine produces the same bytes: a test
// regenerates the files and compares them with the committed copies.
#include <stb_image_write.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct Rgba {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
};

constexpr Rgba kTransparent{0, 0, 0, 0};

// A texture being drawn, starting fully transparent; (0, 0) is the top-left texel.
struct Canvas {
    int width, height;
    std::vector<Rgba> texels;

    Canvas(int w, int h) : width(w), height(h), texels(static_cast<std::size_t>(w) * h, kTransparent) {}
    Rgba& at(int x, int y) { return texels[static_cast<std::size_t>(y) * width + x]; }
};

// The colour `step` of `steps` of the way from `from` to `to`, rounded.
Rgba mix(Rgba from, Rgba to, int step, int steps) {
    auto channel = [&](int a, int b) { return std::uint8_t((a * (steps - step) + b * step + steps / 2) / steps); };
    return {channel(from.r, to.r), channel(from.g, to.g), channel(from.b, to.b), channel(from.a, to.a)};
}

void fill_circle(Canvas& canvas, int cx, int cy, int radius, Rgba colour) {
    for (int y = std::max(0, cy - radius); y <= std::min(canvas.height - 1, cy + radius); ++y) {
        for (int x = std::max(0, cx - radius); x <= std::min(canvas.width - 1, cx + radius); ++x) {
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= radius * radius) canvas.at(x, y) = colour;
        }
    }
}

// ---------------------------------------------------------------------------------------
// The textures

// 8x8 squares; the "dark" squares are fully transparent, the others run from crimson to amber.
Canvas draw_checker() {
    constexpr int kSize = 256, kSquare = 32, kSquares = kSize / kSquare;
    Canvas canvas(kSize, kSize);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const int sx = x / kSquare, sy = y / kSquare;
            if ((sx + sy) % 2 == 0) {
                canvas.at(x, y) = mix({200, 30, 60}, {250, 185, 40}, sx + sy, 2 * (kSquares - 1));
            }
        }
    }
    return canvas;
}

// A tree with apples: opaque inside its outline, transparent outside. The crown shades from
// sunlit yellow-green at the top to deep green at the bottom, the trunk from left to right.
Canvas draw_cutout() {
    constexpr int kSize = 256;
    Canvas canvas(kSize, kSize);
    for (int y = 140; y < 250; ++y) {
        for (int x = 114; x < 142; ++x) canvas.at(x, y) = mix({130, 85, 45}, {70, 45, 25}, x - 114, 27);
    }
    struct Circle {
        int cx, cy, radius;
    };
    const Circle crown[] = {{128, 80, 56}, {84, 112, 46}, {172, 112, 46}, {128, 130, 50}, {98, 68, 40}, {158, 68, 40}};
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            for (const Circle& c : crown) {
                const int dx = x - c.cx, dy = y - c.cy;
                if (dx * dx + dy * dy <= c.radius * c.radius) {
                    canvas.at(x, y) = mix({175, 220, 90}, {30, 100, 40}, y - 24, 156);
                    break;
                }
            }
        }
    }
    const Circle apples[] = {{100, 98, 7}, {150, 80, 7}, {178, 126, 7}, {122, 146, 7}, {72, 128, 7}, {140, 112, 7}};
    for (const Circle& apple : apples) fill_circle(canvas, apple.cx, apple.cy, apple.radius, {205, 35, 40});
    return canvas;
}

// A mountain ridge: the y of its crest at each x, straight lines between (x, y) peaks.
struct Peak {
    int x, y;
};

template <std::size_t N>
int ridge_y(const Peak (&peaks)[N], int x) {
    for (std::size_t i = 1; i < N; ++i) {
        if (x <= peaks[i].x) {
            const Peak& a = peaks[i - 1];
            const Peak& b = peaks[i];
            return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
        }
    }
    return peaks[N - 1].y;
}

// Opaque landscape: sky gradient, sun, clouds, a hazy snow-capped range, a nearer green
// range and a meadow. Drawn back to front.
Canvas draw_backdrop() {
    constexpr int kWidth = 512, kHeight = 256, kHorizon = 176;
    // (x, y) of each peak and saddle, left to right; kFarTop and kNearTop are the highest y.
    constexpr Peak kFarRange[] = {{0, 120},   {60, 80},  {130, 112}, {200, 58}, {270, 104},
                                  {330, 74},  {420, 116}, {470, 70},  {511, 100}};
    constexpr Peak kNearRange[] = {{0, 150}, {90, 122}, {170, 160}, {250, 128}, {340, 166}, {430, 132}, {511, 154}};
    constexpr int kFarTop = 58, kNearTop = 122, kSnowLine = 86;
    Canvas canvas(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            Rgba& texel = canvas.at(x, y);
            if (y >= kHorizon) {
                texel = mix({100, 160, 70}, {40, 95, 35}, y - kHorizon, kHeight - 1 - kHorizon);
            } else if (y >= ridge_y(kNearRange, x)) {
                texel = mix({70, 115, 85}, {45, 80, 60}, y - kNearTop, kHorizon - kNearTop);
            } else if (y >= ridge_y(kFarRange, x) && y < kSnowLine) {
                texel = {235, 240, 250};
            } else if (y >= ridge_y(kFarRange, x)) {
                texel = mix({135, 150, 185}, {105, 125, 165}, y - kFarTop, kHorizon - kFarTop);
            } else {
                texel = mix({35, 85, 170}, {200, 225, 245}, y, kHorizon);
            }
        }
    }
    fill_circle(canvas, 400, 40, 18, {255, 244, 200});
    for (const Peak& cloud : {Peak{90, 36}, Peak{290, 24}}) {
        fill_circle(canvas, cloud.x - 18, cloud.y + 4, 12, {245, 248, 252});
        fill_circle(canvas, cloud.x, cloud.y, 16, {245, 248, 252});
        fill_circle(canvas, cloud.x + 20, cloud.y + 5, 11, {245, 248, 252});
    }
    return canvas;
}

// A green road sign with a white border and an arrow pointing right; opaque.
Canvas draw_sign() {
    constexpr int kWidth = 48, kHeight = 24, kBorder = 2;
    Canvas canvas(kWidth, kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const bool border = x < kBorder || y < kBorder || x >= kWidth - kBorder || y >= kHeight - kBorder;
            const bool shaft = x >= 9 && x < 28 && y >= 10 && y < 14;
            // Arrow head: a triangle from x = 28 (14 texels tall) to its tip at x = 40.
            const bool head = x >= 28 && x < 40 && std::abs(2 * y + 1 - kHeight) * 12 <= 14 * (40 - x);
            canvas.at(x, y) = border || shaft || head ? Rgba{250, 250, 250} : Rgba{20, 110, 60};
        }
    }
    return canvas;
}

// ---------------------------------------------------------------------------------------
// Writing

bool save_png(const std::string& path, const Canvas& canvas, bool keep_alpha) {
    const int channels = keep_alpha ? 4 : 3;
    std::vector<std::uint8_t> bytes;
    for (const Rgba& t : canvas.texels) {
        bytes.insert(bytes.end(), {t.r, t.g, t.b});
        if (keep_alpha) bytes.push_back(t.a);
    }
    return stbi_write_png(path.c_str(), canvas.width, canvas.height, channels, bytes.data(),
                          canvas.width * channels) != 0;
}

// ASCII PPM, which stb_image_write does not offer. Lines stay under 70 characters, as the
// Netpbm format asks.
bool save_ppm_ascii(const std::string& path, const Canvas& canvas, const std::string& comment) {
    std::ofstream out(path, std::ios::binary);
    out << "P3\n# " << comment << "\n" << canvas.width << " " << canvas.height << "\n255\n";
    std::string line;
    for (const Rgba& t : canvas.texels) {
        const std::string texel = std::to_string(t.r) + " " + std::to_string(t.g) + " " + std::to_string(t.b);
        if (!line.empty() && line.size() + 1 + texel.size() > 69) {
            out << line << "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + texel;
    }
    out << line << "\n";
    return static_cast<bool>(out.flush());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2) {
        std::cerr << "usage: " << argv[0] << " [OUTPUT_FOLDER]   (default: scenes/demo)\n";
        return 1;
    }
    const std::filesystem::path folder = argc == 2 ? argv[1] : "scenes/demo";
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    const bool ok = save_png((folder / "checker.png").string(), draw_checker(), true) &&
                    save_png((folder / "cutout.png").string(), draw_cutout(), true) &&
                    save_png((folder / "backdrop.png").string(), draw_backdrop(), false) &&
                    save_ppm_ascii((folder / "sign.ppm").string(), draw_sign(),
                                   "clrender demo sign, drawn by scripts/make_textures.cpp");
    if (!ok) {
        std::cerr << "make_textures: cannot write the textures into " << folder << "\n";
        return 1;
    }
    return 0;
}
