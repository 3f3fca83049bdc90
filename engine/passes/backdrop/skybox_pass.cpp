#include "passes/backdrop/skybox_pass.h"

#include "executor/graph_executor.h"
#include "passes/backdrop/sky_rays.h"
#include "passes/recording/fullscreen.h"

namespace candela::passes {

using namespace graph;

SkyboxPass::SkyboxPass(vk::Context& context) : mContext(context), mSampler(vk::createSampler(context, {})) {}

DrawTarget SkyboxPass::add(RenderGraph& graph, const scene::ViewSetup& view, const Inputs& in,
                          shader::ParameterRegistry* parameters) {
    struct Data {
        DrawTarget target;
        TextureId specular;
        const vk::Pipeline* pipeline = nullptr;
        shading::SkyboxPush push{};
    };
    const Data& data = graph.addPass<Data>(
        "skybox", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.specular = builder.sample(in.specular);
            const bool depthTest = in.target.depth.valid();
            if (depthTest) {
                d.target = drawInto(builder, in.target, false, DepthUse::Test);
            } else {
                d.target = in.target;
                d.target.color = d.target.hdr = builder.writeColor(in.target.color, std::nullopt);
            }
            const VkFormat color = builder.desc(in.target.color).format;
            const VkFormat depth = depthTest ? builder.desc(in.target.depth).format : VK_FORMAT_UNDEFINED;
            const uint32_t samples = builder.desc(in.target.color).samples;
            d.pipeline = &mPipelines.get(mContext, {color, depth, samples}, [&] {
                return vk::Pipeline::graphics(mContext, "fullscreen.vert", "skybox.frag",
                                              {.colorFormats = {color},
                                               .depthFormat = depth,
                                               .depthTest = depthTest,
                                               .depthWrite = false,
                                               .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
                                               .blend = vk::BlendMode::Under,
                                               .samples = samples});
            });
            const TextureDesc& target = builder.desc(in.target.color);
            d.push = {.rays = skyRays(view.viewProjection, view.eye, in.params.rotation, target.width, target.height),
                      .ibl = in.params};
            if (parameters)
                parameters->apply("skybox", "Push", d.pipeline->program().reflection().pushConstants.members, d.push);
        },
        [sampler = mSampler.get()](const Data& d, PassContext& ctx) {
            drawFullscreenSampling(ctx, *d.pipeline, "specularCube", d.specular, sampler, &d.push, sizeof(d.push));
        });
    return data.target;
}

}  // namespace candela::passes
