// candela::Scene and candela::Environment (candela/scene.h): the loaders' results, held.

#include "api/access.h"
#include "candela/errors.h"
#include "candela/scene.h"
#include "assets/builtin_scenes.h"
#include "assets/environment.h"
#include "assets/gltf_loader.h"
#include "assets/procedural_sky.h"

#include <atomic>
#include <cstring>

namespace candela {

uint64_t newObjectId() {
    static std::atomic<uint64_t> next{1};
    return next++;
}

Scene::Scene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Scene::Scene(Scene&&) noexcept = default;
Scene& Scene::operator=(Scene&&) noexcept = default;
Scene::~Scene() = default;

Scene Access::scene(scene::Scene scene) { return Scene(std::make_unique<Scene::Impl>(Scene::Impl{std::move(scene), std::nullopt, newObjectId()})); }

Scene Scene::fromFile(const std::string& path, std::optional<uint32_t> sceneIndex) {
    std::optional<Scene> out;
    // The levels of detail wait for the frames asked (Device::render*: geometry/lod_cost.h).
    translateErrors(path, [&] { out = Access::scene(assets::loadGltf(path, {.sceneIndex = sceneIndex, .deferLevelsOfDetail = true})); });
    return std::move(*out);
}

Scene Scene::fromMemory(std::span<const std::byte> bytes, const std::string& name, const UriResolver& resolver,
                        std::optional<uint32_t> sceneIndex) {
    assets::LoadOptions options{.sceneIndex = sceneIndex, .deferLevelsOfDetail = true};
    // Without a resolver every URI is refused, as the resolver that has no file would.
    options.uriReader = [&resolver](const std::string& uri) -> std::optional<std::vector<uint8_t>> {
        if (!resolver) return std::nullopt;
        std::optional<std::vector<std::byte>> found = resolver(uri);
        if (!found) return std::nullopt;
        std::vector<uint8_t> out(found->size());
        if (!out.empty()) std::memcpy(out.data(), found->data(), out.size());
        return out;
    };
    std::optional<Scene> out;
    translateErrors(name, [&] {
        const std::span<const uint8_t> file(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
        out = Access::scene(assets::loadGltfFromMemory(file, name, options));
    });
    return std::move(*out);
}

Scene Scene::sphereGrid(uint32_t count) {
    std::optional<Scene> out;
    translateErrors("", [&] {
        if (count == 0 || count > 100) throw UserError("sphere grid: " + std::to_string(count) + " spheres a side; give 1 to 100");
        out = Access::scene(assets::makeSphereGrid(count));
    });
    return std::move(*out);
}

const std::string& Scene::name() const { return impl_->scene.source; }

std::vector<std::string> Scene::variants() const { return impl_->scene.variants; }

std::vector<std::string> Scene::animations() const {
    std::vector<std::string> names;
    for (size_t i = 0; i < impl_->scene.animations.size(); ++i) {
        const std::string& name = impl_->scene.animations[i].name;
        names.push_back(name.empty() ? "animation " + std::to_string(i) : name);
    }
    return names;
}

const std::vector<std::string>& Scene::warnings() const { return impl_->scene.report.warnings; }

Environment::Environment(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Environment::Environment(Environment&&) noexcept = default;
Environment& Environment::operator=(Environment&&) noexcept = default;
Environment::~Environment() = default;

Environment Access::environment(assets::Environment environment) {
    return Environment(std::make_unique<Environment::Impl>(Environment::Impl{std::move(environment), newObjectId()}));
}

Environment Environment::fromFile(const std::string& path) {
    std::optional<Environment> out;
    translateErrors(path, [&] { out = Access::environment(assets::loadEnvironment(path)); });
    return std::move(*out);
}

Environment Environment::fromMemory(std::span<const std::byte> bytes, const std::string& name) {
    std::optional<Environment> out;
    translateErrors(name, [&] {
        const std::span<const uint8_t> file(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
        out = Access::environment(assets::decodeEnvironment(file, name));
    });
    return std::move(*out);
}

Environment Environment::sky() { return Access::environment(assets::makeProceduralSky()); }

const std::string& Environment::name() const { return impl_->environment.source; }
uint32_t Environment::width() const { return impl_->environment.width; }
uint32_t Environment::height() const { return impl_->environment.height; }
const std::vector<std::string>& Environment::warnings() const { return impl_->environment.report.warnings; }

}  // namespace candela
