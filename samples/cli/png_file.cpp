#include "png_file.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include <png.h>

#include <hush/core/atomic_file.hpp>
#include <hush/core/error.hpp>

namespace hush::cli {

namespace {
// libpng reports errors through a callback that must not return: it longjmps back
// to setjmp in writePng. No C++ object with a destructor lives across that jump.
void onPngError(png_structp png, png_const_charp message) {
    auto* text = static_cast<std::string*>(png_get_error_ptr(png));
    if (text) *text = message;
    png_longjmp(png, 1);
}
void onPngWarning(png_structp, png_const_charp) {}

// Returns an empty string on success, else libpng's message.
std::string writePngStream(FILE* file, uint32_t width, uint32_t height, const uint8_t* rgb, std::string* error) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, onPngError, onPngWarning);
    if (!png) return "out of memory";
    png_infop info = png_create_info_struct(png);
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return "out of memory";
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return error->empty() ? "libpng error" : *error;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    for (uint32_t y = 0; y < height; ++y) png_write_row(png, rgb + size_t(y) * width * 3);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return {};
}
} // namespace

void writePng(const std::string& path, uint32_t width, uint32_t height, std::span<const uint8_t> rgb) {
    if (width == 0 || height == 0 || rgb.size() != size_t(width) * height * 3)
        throw Error(ErrorKind::InvalidArgument, "cannot write '" + path + "': image data does not match " +
                                                    std::to_string(width) + "x" + std::to_string(height) + " RGB");
    core::writeAtomically(path, [&](const std::string& temporary) {
        FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) throw std::runtime_error("cannot create '" + temporary + "'");
        std::string libpngMessage;
        std::string failure = writePngStream(file, width, height, rgb.data(), &libpngMessage);
        if (std::fclose(file) != 0 && failure.empty()) failure = "could not finish writing (disk full?)";
        if (!failure.empty()) throw std::runtime_error(failure);
    });
}

} // namespace hush::cli
