#include "postimpact/png_io.h"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace postimpact {

namespace {

void write_cb(png_structp p, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(p));
    out->insert(out->end(), data, data + n);
}
void flush_cb(png_structp) {}
void error_cb(png_structp, png_const_charp msg) { throw std::runtime_error(std::string("libpng: ") + msg); }
void warning_cb(png_structp, png_const_charp) {}

}  // namespace

std::vector<unsigned char> encode_png(const Image& img) {
    if (img.width <= 0 || img.height <= 0) throw std::runtime_error("encode_png: empty image");
    std::vector<unsigned char> out;
    png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, error_cb, warning_cb);
    if (!p) throw std::runtime_error("libpng: png_create_write_struct failed");
    png_infop info = png_create_info_struct(p);
    if (!info) {
        png_destroy_write_struct(&p, nullptr);
        throw std::runtime_error("libpng: png_create_info_struct failed");
    }
    std::vector<unsigned char> row(3 * static_cast<std::size_t>(img.width));
    try {
        png_set_write_fn(p, &out, write_cb, flush_cb);
        png_set_IHDR(p, info, img.width, img.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_compression_level(p, 6);
        png_set_filter(p, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB | PNG_FILTER_UP | PNG_FILTER_PAETH);
        png_write_info(p, info);
        for (int y = 0; y < img.height; ++y) {
            const std::uint8_t* s = img.px(0, y);
            for (int x = 0; x < img.width; ++x) {
                row[3 * x] = s[4 * x]; row[3 * x + 1] = s[4 * x + 1]; row[3 * x + 2] = s[4 * x + 2];
            }
            png_write_row(p, row.data());
        }
        png_write_end(p, nullptr);
    } catch (...) {
        png_destroy_write_struct(&p, &info);
        throw;
    }
    png_destroy_write_struct(&p, &info);
    return out;
}

void write_png(const std::string& path, const Image& img) {
    const std::vector<unsigned char> bytes = encode_png(img);
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    f.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!f) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
}

Image read_png(const std::string& path) {
    png_image im;
    std::memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&im, path.c_str()))
        throw std::runtime_error("cannot read PNG " + path + ": " + im.message);
    im.format = PNG_FORMAT_RGBA;
    Image out;
    out.width = static_cast<int>(im.width);
    out.height = static_cast<int>(im.height);
    out.rgba.resize(PNG_IMAGE_SIZE(im));
    if (!png_image_finish_read(&im, nullptr, out.rgba.data(), 0, nullptr)) {
        png_image_free(&im);
        throw std::runtime_error("cannot read PNG " + path + ": " + im.message);
    }
    return out;
}

}  // namespace postimpact
