// LoadOptions::uriReader (the public API's UriResolver): external URIs of a glTF in memory read
// through the reader, after the same checks files get; what it lacks is one error naming the URI.

#include "gltf_test_util.h"

#include <gtest/gtest.h>

#include <map>

namespace candela::assets::test::gltf_uri_reader_test {
namespace {

struct Reader {
    std::map<std::string, Bytes> files;
    std::vector<std::string> asked;
    UriReader reader() {
        return [this](const std::string& uri) -> std::optional<std::vector<uint8_t>> {
            asked.push_back(uri);
            const auto it = files.find(uri);
            if (it == files.end()) return std::nullopt;
            return it->second;
        };
    }
};

scene::Scene loadJson(const std::string& json, const UriReader& reader) {
    LoadOptions options;
    options.uriReader = reader;
    return loadGltfFromMemory(std::span(reinterpret_cast<const uint8_t*>(json.data()), json.size()), "memory/model.gltf", options);
}

std::string errorOf(const std::string& json, const UriReader& reader) {
    try {
        loadJson(json, reader);
    } catch (const UserError& e) {
        return e.what();
    }
    return "";
}

TEST(GltfUriReader, ReadsTheBufferAndTheImageThroughTheReader) {
    const GltfBuilder model = texturedTriangle("texture.png");
    Reader files{{{"model.bin", model.bin}, {"texture.png", smallPng()}}, {}};
    const scene::Scene scene = loadJson(model.withBuffer("model.bin").dump(), files.reader());
    EXPECT_EQ(scene.draws.size(), 1u);
    ASSERT_EQ(scene.images.size(), 1u);
    EXPECT_EQ(scene.images[0].width, 2u);
    EXPECT_NE(std::find(files.asked.begin(), files.asked.end(), "model.bin"), files.asked.end());
    EXPECT_NE(std::find(files.asked.begin(), files.asked.end(), "texture.png"), files.asked.end());
}

TEST(GltfUriReader, AFileTheReaderLacksIsOneErrorNamingTheUri) {
    const GltfBuilder model = texturedTriangle("texture.png");
    Reader files{{{"model.bin", model.bin}}, {}};
    EXPECT_EQ(errorOf(model.withBuffer("model.bin").dump(), files.reader()),
              "memory/model.gltf: cannot read 'texture.png': the URI resolver has no such file");
    Reader empty{{{"model.bin", {}}}, {}};
    EXPECT_NE(errorOf(model.withBuffer("model.bin").dump(), empty.reader()).find("'model.bin': empty file"), std::string::npos);
}

TEST(GltfUriReader, UrisLeavingTheFolderOrNamingASchemeNeverReachTheReader) {
    GltfBuilder model;
    model.addTriangle();
    for (const std::string uri : {"../model.bin", "/etc/passwd", "file:model.bin", "a/../../model.bin"}) {
        Reader files{{{uri, model.bin}}, {}};
        const std::string error = errorOf(model.withBuffer(uri).dump(), files.reader());
        EXPECT_NE(error.find("URI '"), std::string::npos) << uri << ": " << error;
        EXPECT_TRUE(files.asked.empty()) << uri;
    }
}

}  // namespace
}  // namespace candela::assets::test::gltf_uri_reader_test
