#include "passes/skybox_pass.h"

#include "graph/graph_executor.h"
#include "passes/forward_pass.h"
#include "passes/fullscreen.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace candela::passes {

using namespace graph;

SkyboxPass::SkyboxPass(vk::Context& context)
    : mContext(context),
      mPipeline(vk::Pipeline::graphics(context, "fullscreen.vert", "skybox.frag",
                                       {.colorFormats = {ForwardPass::kHdrFormat},
                                        .depthFormat = ForwardPass::kDepthFormat,
                                        .depthTest = true,
                                        .depthWrite = false,
                                        .depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL,
                                        .blend = vk::BlendMode::Under})) {}

TextureId SkyboxPass::add(RenderGraph& graph, const scene::ViewSetup& view, const Inputs& in,
                          shader::ParameterRegistry* parameters) {
    mPipeline.refresh(mContext);  // a shader replaced at run time (hot reload)
    struct Data {
        TextureId hdr;
        TextureId depth;
        TextureId specular;
    };
    shading::SkyboxPush push{.inverseViewProjection = glm::inverse(view.viewProjection),
                                   .eye = glm::vec4(view.eye, 1.0f),
                                   .ibl = in.params};
    if (parameters) parameters->apply("skybox", "Push", mPipeline.program().reflection().pushConstants.members, push);
    const Data& data = graph.addPass<Data>(
        "skybox", PassType::Graphics,
        [&](PassBuilder& builder, Data& d) {
            d.specular = builder.read(in.specular, Usage::Sampled);
            d.depth = builder.read(in.depth, Usage::DepthRead);
            d.hdr = builder.writeColor(in.hdr, std::nullopt);
        },
        [this, push, view = in.specularView, sampler = in.sampler](const Data&, PassContext& ctx) {
            const VkDescriptorSet set = vk::DescriptorWriter(mPipeline.program(), 0)
                                            .image("specularCube", view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler)
                                            .commit(ctx.context(), ctx.descriptors());
            drawFullscreenTriangle(ctx, mPipeline, set, &push, sizeof(push));
        });
    return data.hdr;
}

}  // namespace candela::passes
