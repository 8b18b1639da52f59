// tools/render/png.cpp -- PNG output of the renderer through stb_image_write.h (Debian's
// libstb-dev), whose implementation is compiled here, once.
#include "render.h"

#include <PCCD/Error.h>

#include <filesystem>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace pccd_render {

void write_png(const std::string& path, const Image& image)
{
    if (image.width <= 0 || image.height <= 0 ||
        image.rgb.size() != 3 * std::size_t(image.width) * std::size_t(image.height))
        throw PCCD::Invalid_input("write_png: the image is empty or its pixels do not match its size");
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent))
        throw PCCD::File_error(path, "cannot write the PNG file: the directory " + parent.string() + " does not exist");
    if (stbi_write_png(path.c_str(), image.width, image.height, 3, image.rgb.data(), 3 * image.width) == 0)
        throw PCCD::File_error(path, "cannot write the PNG file");
}

} // namespace pccd_render
