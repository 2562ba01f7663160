// marchbox/gl/image.h — RGBA8 images, PNG files, and the comparisons the tests and the render
// report use.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace mb {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgba;  // row 0 is the top of the picture

    uint8_t* pixel(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
    const uint8_t* pixel(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

Image makeImage(int width, int height);
// An image from width × height RGBA8 pixels whose rows run from the bottom, as GL reads them.
Image imageFromBottomUp(const uint8_t* rows, int width, int height);
bool savePng(const std::string& path, const Image& img, std::string* error);
// The two halves of savePng, for encoding on one thread and writing on another: the PNG's
// bytes ("" where it cannot be encoded), and those bytes written to `path` as savePng does.
std::string encodePng(const Image& img);
bool savePngBytes(const std::string& path, const std::string& png, std::string* error);
// Whether savePng could write `path` (checkReplaceFile), *error in its words: before a long render.
bool checkSavePng(const std::string& path, std::string* error);
bool loadPng(const std::string& path, Image* out, std::string* error);

struct ImageDiff {
    double meanAbs = 0;  // mean |a-b| over all RGB channels, in 0..255 units
    double p99 = 0;      // 99th percentile of the per-pixel max channel difference
    double maxAbs = 0;
    Image visual;  // per-pixel max channel difference, amplified ×8, as grey
};

// Requires equal sizes; the caller checks.
ImageDiff diffImages(const Image& a, const Image& b);

// Root-mean-square difference over the RGB channels, in 0..255 units. Requires equal sizes.
double rmse(const Image& a, const Image& b);
// Peak signal-to-noise ratio over RGB in dB, 20·log10(255 / rmse). Identical pictures (rmse 0)
// score +infinity, the true limit: no stand-in figure that a real difference could also reach.
double psnrFromRmse(double rmse);
double psnr(const Image& a, const Image& b);

// n×n box filter: an image rendered at n times the size (a multiple of n), averaged down.
Image boxDownsample(const Image& big, int n);

}  // namespace mb
