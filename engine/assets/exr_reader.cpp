#include "assets/exr_reader.h"

#include "core/errors.h"

#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputPart.h>
#include <OpenEXR/ImfMultiPartInputFile.h>
#include <OpenEXR/ImfThreading.h>
#include <openexr.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <exception>
#include <optional>
#include <thread>
#include <vector>

namespace candela::assets {
namespace {

[[noreturn]] void failExr(const std::string& source, const std::string& problem) {
    throw UserError(source + ": " + problem);
}

// One line without control characters, from OpenEXR's messages, exceptions and part names.
std::string oneLine(const char* text) {
    std::string out;
    for (const char* c = text; *c && out.size() < 300; ++c)
        if (static_cast<unsigned char>(*c) >= 0x20) out += *c;
        else if (!out.empty() && out.back() != ' ') out += ' ';
    while (!out.empty() && out.back() == ' ') out.pop_back();
    return out.empty() ? std::string("unknown error") : out;
}

// The file in memory, and the first message OpenEXR reported for it (its error callback may
// fire several times for one failure; the first names the cause).
struct Stream {
    std::span<const uint8_t> bytes;
    std::string message;
};

int64_t readBytes(exr_const_context_t, void* user, void* buffer, uint64_t size, uint64_t offset,
                  exr_stream_error_func_ptr_t) {
    const auto& bytes = static_cast<const Stream*>(user)->bytes;
    if (offset >= bytes.size()) return 0;
    const uint64_t count = std::min<uint64_t>(size, bytes.size() - offset);
    std::memcpy(buffer, bytes.data() + offset, count);
    return int64_t(count);
}

int64_t streamSize(exr_const_context_t, void* user) { return int64_t(static_cast<const Stream*>(user)->bytes.size()); }

void keepMessage(exr_const_context_t context, exr_result_t, const char* message) {
    void* user = nullptr;
    if (exr_get_user_data(context, &user) != EXR_ERR_SUCCESS || !user || !message) return;
    std::string& kept = static_cast<Stream*>(user)->message;
    if (kept.empty()) kept = oneLine(message);
}

// Owns an open OpenEXRCore read context: the headers parsed and validated.
class Context {
public:
    Context(Stream& stream, const std::string& source, const EnvironmentLoadOptions& options)
        : mStream(stream), mSource(source) {
        exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
        init.error_handler_fn = keepMessage;
        init.user_data = &stream;
        init.read_fn = readBytes;
        init.size_fn = streamSize;
        // A data window beyond what we could display is refused while the header is parsed,
        // before OpenEXR sizes any table or buffer from it.
        init.max_image_width = int(options.maxWidth);
        init.max_image_height = int(options.maxHeight);
        init.max_tile_width = int(options.maxWidth);
        init.max_tile_height = int(options.maxHeight);
        // Strict: a malformed attribute or a missing required one is an error. Leniently,
        // OpenEXRCore reports a bad attribute, stops reading the header and fills what it missed
        // with defaults, and the C++ library, which trusts stated sizes and reads on, then sizes
        // its buffers from values nothing validated (three fuzz findings, docs/fuzzing.md 8–10).
        init.flags = EXR_CONTEXT_FLAG_STRICT_HEADER | EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
        check(exr_start_read(&mContext, source.c_str(), &init));
    }
    ~Context() { exr_finish(&mContext); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    exr_const_context_t get() const { return mContext; }

    // Throws "SOURCE: invalid EXR header: OpenEXR's message" unless `result` is success.
    void check(exr_result_t result) const {
        if (result == EXR_ERR_SUCCESS) return;
        const std::string detail = !mStream.message.empty() ? mStream.message : exr_get_default_error_message(result);
        failExr(mSource, "invalid EXR header: " + detail);
    }

private:
    Stream& mStream;
    const std::string& mSource;
    exr_context_t mContext = nullptr;
};

struct Box {
    int64_t minX, minY, maxX, maxY;
    bool operator==(const Box&) const = default;
    int64_t width() const { return maxX - minX + 1; }
    int64_t height() const { return maxY - minY + 1; }
    std::string text() const {
        return "(" + std::to_string(minX) + "," + std::to_string(minY) + ")-(" + std::to_string(maxX) + "," +
               std::to_string(maxY) + ")";
    }
};
Box box(const exr_attr_box2i_t& b) { return {b.min.x, b.min.y, b.max.x, b.max.y}; }
Box box(const Imath::Box2i& b) { return {b.min.x, b.min.y, b.max.x, b.max.y}; }

// The channels a part offers for colour: R, G, B, or Y for grey (names as written, no layers).
struct ColourChannels {
    std::array<std::string, 3> names;  // R, G, B, or Y three times
    bool grey = false;
};

std::optional<ColourChannels> colourChannels(const exr_attr_chlist_t& list) {
    bool r = false, g = false, b = false, y = false;
    for (int c = 0; c < list.num_channels; ++c) {
        const std::string name(list.entries[c].name.str, size_t(list.entries[c].name.length));
        r |= name == "R";
        g |= name == "G";
        b |= name == "B";
        y |= name == "Y";
    }
    if (r && g && b) return ColourChannels{{"R", "G", "B"}, false};
    if (y) return ColourChannels{{"Y", "Y", "Y"}, true};
    return std::nullopt;
}

// Refuses what the chosen channels cannot give: UINT samples, sub-sampling, and a Y channel with
// chroma beside it (a luminance/chroma file, which is not grey).
void checkColourChannels(const exr_attr_chlist_t& list, const ColourChannels& colour, const std::string& source) {
    for (int c = 0; c < list.num_channels; ++c) {
        const exr_attr_chlist_entry_t& entry = list.entries[c];
        const std::string name(entry.name.str, size_t(entry.name.length));
        if (colour.grey && (name == "RY" || name == "BY"))
            failExr(source, "luminance/chroma EXR (Y, RY, BY) is not supported; save it as RGB");
        if (std::find(colour.names.begin(), colour.names.end(), name) == colour.names.end()) continue;
        if (entry.pixel_type != EXR_PIXEL_HALF && entry.pixel_type != EXR_PIXEL_FLOAT)
            failExr(source, "channel " + name + " is UINT; only HALF and FLOAT are supported");
        if (entry.x_sampling != 1 || entry.y_sampling != 1) failExr(source, "channel " + name + " is sub-sampled; not supported");
    }
}

// The part to read: the first non-deep part with colour channels.
struct Choice {
    int part = -1;
    ColourChannels colour;
    int parts = 0;  // in the file
};

Choice choosePart(const Context& context, const std::string& source) {
    int parts = 0;
    context.check(exr_get_count(context.get(), &parts));
    int deep = 0;
    for (int p = 0; p < parts; ++p) {
        exr_storage_t storage{};
        context.check(exr_get_storage(context.get(), p, &storage));
        if (storage == EXR_STORAGE_DEEP_SCANLINE || storage == EXR_STORAGE_DEEP_TILED) {
            ++deep;
            continue;
        }
        const exr_attr_chlist_t* list = nullptr;
        context.check(exr_get_channels(context.get(), p, &list));
        if (auto colour = colourChannels(*list)) {
            checkColourChannels(*list, *colour, source);
            return {p, *colour, parts};
        }
    }
    if (deep == parts) failExr(source, "deep EXR is not supported (it holds samples at depths, not one colour per pixel)");
    failExr(source, parts > 1 ? "no part with R, G, B (or Y) channels in this " + std::to_string(parts) + "-part EXR"
                           : "no R, G, B (or Y) channels");
}

// The file in memory as OpenEXR's C++ library reads it: every read is bounds-checked.
class MemoryStream final : public Imf::IStream {
public:
    explicit MemoryStream(std::span<const uint8_t> bytes) : Imf::IStream("(memory)"), mBytes(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || uint64_t(n) > mBytes.size() - mPosition) throw std::runtime_error("unexpected end of file");
        std::memcpy(c, mBytes.data() + mPosition, size_t(n));
        mPosition += uint64_t(n);
        return mPosition < mBytes.size();
    }
    uint64_t tellg() override { return mPosition; }
    void seekg(uint64_t position) override {
        if (position > mBytes.size()) throw std::runtime_error("seek past the end of the file");
        mPosition = position;
    }

private:
    std::span<const uint8_t> mBytes;
    uint64_t mPosition = 0;
};

// OpenEXR decodes chunks on its process-wide thread pool: sized once, to the machine's cores.
int decodeThreads() {
    static const int threads = [] {
        const int n = int(std::max(1u, std::thread::hardware_concurrency()));
        Imf::setGlobalThreadCount(n);
        return n;
    }();
    return threads;
}

// Decodes the rows of `part` that meet the display window into `env` (display-window sized,
// zero-filled) through OpenEXR's C++ library, which converts HALF to FLOAT and reads scanline and
// tiled parts alike (tiled: level 0). The headers were validated by OpenEXRCore before. When the
// data window's columns lie within the display window (nearly every file) the library writes into
// `env` directly; otherwise (overscan) whole data rows go to a scratch block first and the display
// part is copied out. Y lands in R and is copied to G and B.
void decodePixels(std::span<const uint8_t> bytes, int part, const ColourChannels& colour, const Box& data,
                  const Box& display, Environment& env) {
    const int64_t y0 = std::max(data.minY, display.minY), y1 = std::min(data.maxY, display.maxY);
    const int64_t x0 = std::max(data.minX, display.minX), x1 = std::min(data.maxX, display.maxX);
    if (y0 > y1 || x0 > x1) return;  // no data inside the picture
    MemoryStream stream(bytes);
    // A corrupt chunk table is an error, not a reason to scan the file for chunks.
    Imf::MultiPartInputFile file(stream, decodeThreads(), /*reconstructChunkOffsetTable=*/false);
    // The C++ library must have read the windows OpenEXRCore validated before it sizes any buffer
    // from them (it parses the headers itself; strict validation makes both read the same).
    if (part >= file.parts()) throw std::runtime_error("OpenEXR's libraries count the parts differently");
    const Imath::Box2i cppData = file.header(part).dataWindow(), cppDisplay = file.header(part).displayWindow();
    if (box(cppData) != data || box(cppDisplay) != display)
        throw std::runtime_error("OpenEXR's libraries read the header's windows differently");
    Imf::InputPart input(file, part);

    const bool direct = data.minX >= display.minX && data.maxX <= display.maxX;
    const int64_t rows = y1 - y0 + 1;
    std::vector<float> scratch(direct ? 0 : size_t(data.width()) * size_t(rows) * 3);
    float* target = direct ? env.texel(uint32_t(data.minX - display.minX), uint32_t(y0 - display.minY)) : scratch.data();
    const size_t rowStride = (direct ? size_t(env.width) : size_t(data.width())) * 3 * sizeof(float);
    Imf::FrameBuffer frame;
    for (size_t k = 0; k < (colour.grey ? 1u : 3u); ++k)
        frame.insert(colour.names[k], Imf::Slice::Make(Imf::FLOAT, target + k, Imath::V2i(int(data.minX), int(y0)),
                                                       data.width(), rows, 3 * sizeof(float), rowStride));
    input.setFrameBuffer(frame);
    input.readPixels(int(y0), int(y1));

    for (int64_t y = y0; y <= y1; ++y) {
        float* to = env.texel(uint32_t(x0 - display.minX), uint32_t(y - display.minY));
        const float* from = direct ? to : scratch.data() + (size_t(y - y0) * size_t(data.width()) + size_t(x0 - data.minX)) * 3;
        if (!direct || colour.grey)
            for (int64_t x = x0; x <= x1; ++x, from += 3, to += 3) {
                const float r = from[0], g = colour.grey ? r : from[1], b = colour.grey ? r : from[2];
                to[0] = r, to[1] = g, to[2] = b;
            }
    }
}

}  // namespace

bool looksLikeExr(std::span<const uint8_t> bytes) {
    return bytes.size() >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

Environment decodeExr(std::span<const uint8_t> bytes, const std::string& source, const EnvironmentLoadOptions& options) {
    if (!looksLikeExr(bytes)) failExr(source, "not an OpenEXR file (bad magic number)");
    if (bytes.size() < 8) failExr(source, "truncated EXR (" + std::to_string(bytes.size()) + " bytes)");
    Stream stream{bytes, {}};
    const Context context(stream, source, options);
    const Choice choice = choosePart(context, source);
    const int part = choice.part;
    exr_const_context_t ctx = context.get();

    exr_attr_box2i_t dataBox{}, displayBox{};
    context.check(exr_get_data_window(ctx, part, &dataBox));
    context.check(exr_get_display_window(ctx, part, &displayBox));
    const Box data = box(dataBox), display = box(displayBox);
    if (display.width() <= 0 || display.height() <= 0)
        failExr(source, "empty or inverted EXR display window " + display.text());
    checkEnvironmentSize(source, uint64_t(display.width()), uint64_t(display.height()), options);

    Environment env;
    env.source = source;
    env.width = uint32_t(display.width());
    env.height = uint32_t(display.height());
    env.rgb.assign(env.texelCount() * 3, 0.0f);

    if (choice.parts > 1) {
        const char* name = nullptr;
        const std::string named = exr_get_name(ctx, part, &name) == EXR_ERR_SUCCESS && name && *name ? " '" + oneLine(name) + "'" : "";
        env.report.notes.push_back(source + ": " + std::to_string(choice.parts) + "-part EXR: part " + std::to_string(part) + named +
                            " used (the first with " + (choice.colour.grey ? "Y" : "R, G, B") + ")");
    }
    const bool covered = data.minX <= display.minX && data.minY <= display.minY && data.maxX >= display.maxX &&
                         data.maxY >= display.maxY;
    if (!covered)
        env.report.notes.push_back(source + ": the data window " + data.text() + " does not cover the display window " +
                            display.text() + "; the rest is black");

    try {
        decodePixels(bytes, part, choice.colour, data, display, env);
    } catch (const std::exception& e) {
        failExr(source, "cannot decode EXR pixels: " + oneLine(e.what()));
    }
    return env;
}

}  // namespace candela::assets
