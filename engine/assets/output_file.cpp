#include "assets/output_file.h"

#include "core/cache_files.h"
#include "core/errors.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <Imath/ImathBox.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace candela::assets {

namespace {

void checkPlane(const std::filesystem::path& path, uint32_t width, uint32_t height, const OutputPlane& plane) {
    const size_t want = size_t(width) * height * plane.channels.size();
    const size_t have = plane.integer ? plane.ids.size() : plane.floats.size();
    if (plane.channels.empty() || want != have)
        throw UserError(path.string() + ": internal error: output " + plane.name + " holds " + std::to_string(have) + " values, not " +
                        std::to_string(want));
}

std::string oneLine(std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' ');
    return message;
}

}  // namespace

void writeOutputsExr(const std::filesystem::path& path, uint32_t width, uint32_t height, std::span<const float> rgba,
                     std::span<const OutputPlane> planes) {
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    std::vector<Imath::half> halves(rgba.begin(), rgba.end());
    if (!rgba.empty()) {
        if (rgba.size() != size_t(width) * height * 4) throw UserError(path.string() + ": internal error: colour size");
        const char* names[] = {"R", "G", "B", "A"};
        char* base = reinterpret_cast<char*>(halves.data());
        for (size_t c = 0; c < 4; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::HALF));
            frame.insert(names[c], Imf::Slice(Imf::HALF, base + c * sizeof(Imath::half), 4 * sizeof(Imath::half),
                                              size_t(width) * 4 * sizeof(Imath::half)));
        }
    }
    for (const OutputPlane& plane : planes) {
        checkPlane(path, width, height, plane);
        const size_t channels = plane.channels.size();
        const Imf::PixelType type = plane.integer ? Imf::UINT : Imf::FLOAT;
        // OpenEXR reads through a non-const pointer even when writing.
        char* base = plane.integer ? reinterpret_cast<char*>(const_cast<uint32_t*>(plane.ids.data()))
                                   : reinterpret_cast<char*>(const_cast<float*>(plane.floats.data()));
        for (size_t c = 0; c < channels; ++c) {
            header.channels().insert(plane.channels[c], Imf::Channel(type));
            frame.insert(plane.channels[c], Imf::Slice(type, base + c * 4, channels * 4, size_t(width) * channels * 4));
        }
    }
    Imf::StdOSStream encoded;  // in memory, then written atomically
    try {
        Imf::OutputFile file(encoded, header);
        file.setFrameBuffer(frame);
        file.writePixels(static_cast<int>(height));
    } catch (const std::exception& e) {
        throw UserError(path.string() + ": cannot write EXR: " + oneLine(e.what()));
    }
    const std::string bytes = encoded.str();
    writeFileAtomically(path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
}

void writeNpy(const std::filesystem::path& path, uint32_t width, uint32_t height, const OutputPlane& plane) {
    checkPlane(path, width, height, plane);
    const size_t channels = plane.channels.size();
    std::string header = std::string("{'descr': '") + (plane.integer ? "<u4" : "<f4") + "', 'fortran_order': False, 'shape': (" +
                         std::to_string(height) + ", " + std::to_string(width) + (channels > 1 ? ", " + std::to_string(channels) : "") +
                         "), }";
    // The magic, version and length take 10 bytes; the header is padded with spaces and ends in a
    // newline so that the data starts at a multiple of 64.
    header.append(63 - (10 + header.size()) % 64, ' ');
    header.push_back('\n');
    const uint16_t length = uint16_t(header.size());
    writeFileAtomically(path, [&](std::ostream& out) {
        out.write("\x93NUMPY\x01\x00", 8);
        const char le[2] = {char(length & 0xFF), char(length >> 8)};
        out.write(le, 2);
        out << header;
        const char* data = plane.integer ? reinterpret_cast<const char*>(plane.ids.data()) : reinterpret_cast<const char*>(plane.floats.data());
        out.write(data, std::streamsize(size_t(width) * height * channels * 4));
    });
}

bool npyComplete(std::span<const uint8_t> bytes) {
    if (bytes.size() < 10 || std::memcmp(bytes.data(), "\x93NUMPY\x01\x00", 8) != 0) return false;
    const size_t length = size_t(bytes[8]) | size_t(bytes[9]) << 8;
    if (bytes.size() < 10 + length) return false;
    const std::string header(reinterpret_cast<const char*>(bytes.data()) + 10, length);
    const size_t open = header.find("'shape': ("), close = header.find(')', open);
    if (open == std::string::npos || close == std::string::npos || header.find("'<") == std::string::npos) return false;
    size_t values = 1;
    std::string dims = header.substr(open + 10, close - open - 10);
    for (size_t at = 0; at < dims.size();) {
        const size_t comma = dims.find(',', at);
        const std::string dim = dims.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
        if (dim.find_first_not_of(' ') != std::string::npos) {
            size_t n = 0;
            for (char c : dim) {
                if (c == ' ') continue;
                if (c < '0' || c > '9' || n > (size_t(1) << 40)) return false;
                n = n * 10 + size_t(c - '0');
            }
            if (n != 0 && values > bytes.size() / n) return false;  // more values than the file has bytes
            values *= n;
        }
        if (comma == std::string::npos) break;
        at = comma + 1;
    }
    return bytes.size() == 10 + length + values * 4;  // every type written here is 4 bytes
}

bool exrDecodesWhole(const std::filesystem::path& path) {
    try {
        Imf::InputFile file(path.string().c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const size_t width = size_t(window.max.x - window.min.x + 1), height = size_t(window.max.y - window.min.y + 1);
        if (width == 0 || height == 0 || width * height > (size_t(1) << 28)) return false;
        std::vector<std::vector<uint32_t>> storage;
        Imf::FrameBuffer frame;
        for (auto c = file.header().channels().begin(); c != file.header().channels().end(); ++c) {
            storage.emplace_back(width * height);
            // Every channel read as 32 bits (a half widened to float).
            const Imf::PixelType type = c.channel().type == Imf::UINT ? Imf::UINT : Imf::FLOAT;
            char* base = reinterpret_cast<char*>(storage.back().data()) -
                         (ptrdiff_t(window.min.x) + ptrdiff_t(window.min.y) * ptrdiff_t(width)) * 4;
            frame.insert(c.name(), Imf::Slice(type, base, 4, width * 4));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return file.isComplete();
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace candela::assets
