#pragma once
// SheenLut: the persistent sheen albedo LUT (passes/ibl/ibl_sheen_lut_pass.h) of KHR_materials_sheen.
// It depends on no environment or setting, so it is computed once — by the first frame whose scene
// has a sheen material — and imported into every later frame that needs it; frames without sheen
// never see it.
//
//     graph::TextureId lut = sheenLut.addToGraph(graph, imports);  // + the pass, the first time
//     ... execute, wait ...
//     sheenLut.frameCompleted(graph);

#include "executor/graph_executor.h"
#include "graph/render_graph.h"
#include "vk/image.h"

#include <memory>
#include <string>

namespace candela::passes {
class IblSheenLutPass;
}

namespace candela::ibl_maps {

class SheenLut {
public:
    explicit SheenLut(vk::Context& context);
    ~SheenLut();

    // Imports the LUT into `graph` (binding it in `imports`), preceded by the pass computing it
    // while it has not been computed. This object must outlive the graph's execution.
    graph::TextureId addToGraph(graph::RenderGraph& graph, graph::ImportBindings& imports);
    // After that graph executed and completed: the LUT counts as computed if its pass ran.
    void frameCompleted(const graph::RenderGraph& graph);
    bool computed() const { return mComputed; }

    static constexpr uint32_t kSize = 32;

private:
    vk::Context& mContext;
    vk::Image mImage;
    std::unique_ptr<passes::IblSheenLutPass> mPass;
    bool mComputed = false;
    bool mAdded = false;
};

}  // namespace candela::ibl_maps
